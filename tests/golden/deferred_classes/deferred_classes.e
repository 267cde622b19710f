note
	description: "Deferred classes and features effected in descendants (as attributes, constants or routines)."

class
	DEFERRED_CLASSES

create
	make

feature {NONE} -- Initialization

	make
		local
			sensors: ARRAY [SENSOR]
			c: COUNTER_SENSOR
		do
			create c
			sensors := <<create {THERMOMETER}.make (21), c>>
			across sensors is s loop
				print (s.reading + " calibrated: " + s.is_calibrated.out + "%N")
			end
			across sensors is s loop
				print (s.reading + " calibrated: " + s.is_calibrated.out + "%N")
			end
			print ("count " + c.count.out + "%N")
		end

end
