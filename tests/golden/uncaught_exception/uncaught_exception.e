note
	description: "An exception nobody rescues ends the program: exit 3 and an Eiffel trace on stderr."

class
	UNCAUGHT_EXCEPTION

create
	make

feature {NONE} -- Initialization

	make
		do
			print ("before%N")
			level_one
			print ("not reached%N")
		end

feature {NONE} -- Implementation

	level_one
		do
			level_two (3)
		end

	level_two (n: INTEGER)
		local
			e: DEVELOPER_EXCEPTION
		do
			create e
			e.set_description ("gave up at level " + n.out)
			e.raise
		end

end
