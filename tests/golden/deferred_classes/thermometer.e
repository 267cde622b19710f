class
	THERMOMETER

inherit
	SENSOR
		redefine
			scale
		end

create
	make

feature {NONE} -- Initialization

	make (t: INTEGER)
		do
			raw := t
			is_calibrated := True
		end

feature -- Access

	name: STRING = "thermometer"

	raw: INTEGER

	scale: INTEGER
		do
			Result := 10
		end

	is_calibrated: BOOLEAN

end
