class
	COUNTER_SENSOR

inherit
	SENSOR

feature -- Access

	name: STRING
		do
			Result := "counter"
		end

	raw: INTEGER
		do
			count := count + 1
			Result := count
		end

	count: INTEGER

	is_calibrated: BOOLEAN
		do
			Result := count > 1
		end

end
