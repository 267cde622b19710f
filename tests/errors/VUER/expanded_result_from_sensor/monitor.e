note
	description: "Polls a thermometer."

class
	MONITOR

create
	make

feature {NONE} -- Initialization

	make
			-- Create a thermometer and poll it.
		local
			l_sensor: separate THERMOMETER
		do
			create l_sensor.make
			poll (l_sensor)
		end

feature -- Basic operations

	poll (a_sensor: separate THERMOMETER)
			-- Print what `a_sensor' measured last.
		local
			r: READING
			p: POSITION
			v: INTEGER
		do
			r := a_sensor.last_reading -- E: VUER
			v := a_sensor.last_value
			p := a_sensor.position
			print (v)
			print (p.x)
			print (r.value)
		end

end
