note
	description: "A percent escape with a letter that Eiffel does not define."

class
	BAD_ESCAPE

create
	make

feature {NONE} -- Initialization

	make
			-- Print a line.
		do
			print ("tab:%ksomething%N") -- E: SYNTAX-LEXICAL
		end

end
