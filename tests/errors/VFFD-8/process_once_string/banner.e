note
	description: "Prints the program's banner."

class
	BANNER

create
	make

feature {NONE} -- Initialization

	make
			-- Print the version, the title and a greeting.
		do
			print (version + "%N")
			print (title + "%N")
			print (greeting + "%N")
			print (signature + "%N")
			announce
		end

feature -- Access

	version: STRING -- E: VFFD(8)
			-- Version of the program.
		once ("process")
			Result := "1.2"
		end

	title: STRING
			-- Title of the program.
		once ("THREAD")
			Result := "rover"
		end

	greeting: STRING
			-- Greeting, one per processor.
		once
			Result := "welcome"
		end

	signature: STRING
			-- Signature, one per object.
		once ("OBJECT")
			Result := "-- the rover team"
		end

feature -- Basic operations

	announce
			-- Print the announcement, once in the whole program.
		once ("PROCESS")
			print ("ready%N")
		end

end
