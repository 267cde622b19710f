deferred class
	SENSOR

feature -- Access

	name: STRING
		deferred
		end

	raw: INTEGER
		deferred
		end

	reading: STRING
			-- Template method: the effective descendants say what `raw' and `scale' are.
		do
			Result := name + " reads " + (raw * scale).out
		end

	scale: INTEGER
		do
			Result := 1
		end

	is_calibrated: BOOLEAN
		deferred
		end

end
