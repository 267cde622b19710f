note
	description: "`end' is a keyword and cannot name an argument."

class
	RESERVED_END_ARGUMENT

create
	make

feature {NONE} -- Initialization

	make
		do
			print_range (1, 5)
		end

feature -- Output

	print_range (start, end: INTEGER) -- E: SYNTAX-RESERVED
			-- Print the numbers from `start'.
		do
			print (start.out + "%N")
		end

end
