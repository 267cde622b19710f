note
	description: "A measured value and where it comes from, copied on assignment."

expanded class
	SAMPLE

feature -- Access

	source: STRING
			-- Name of the station.
		attribute
			Result := "unknown"
		end

	value: INTEGER
			-- The value.

feature -- Element change

	set (a_source: STRING; a_value: INTEGER)
			-- Sample of `a_value' from `a_source'.
		do
			source := a_source
			value := a_value
		end

end
