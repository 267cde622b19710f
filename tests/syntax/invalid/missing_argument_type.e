note
	description: "An argument without a type."

class
	MISSING_ARGUMENT_TYPE

create
	make

feature {NONE} -- Initialization

	make
		do
			show (3)
		end

feature -- Output

	show (n) -- E: SYNTAX
		do
			print (n)
		end

end
