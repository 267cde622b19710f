note
	description: "Two classes in one file."

class
	TWO_CLASSES

create
	make

feature {NONE} -- Initialization

	make
		do
			print ("first%N")
		end

end

class -- E: SYNTAX-CLASS
	SECOND_CLASS

end
