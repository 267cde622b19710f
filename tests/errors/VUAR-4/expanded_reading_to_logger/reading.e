note
	description: "A labelled sensor value, copied on assignment."

expanded class
	READING

feature -- Access

	label: STRING
			-- What was measured.
		attribute
			Result := "none"
		end

	value: INTEGER
			-- The value measured.

feature -- Element change

	set (a_label: STRING; a_value: INTEGER)
			-- Set `label' to `a_label' and `value' to `a_value'.
		do
			label := a_label
			value := a_value
		end

end
