note
	description: "`old' is a keyword: assigning to it as if it were a variable is a syntax error."

class
	RESERVED_OLD_ASSIGNMENT

create
	make

feature {NONE} -- Initialization

	make
			-- Keep the previous value.
		local
			value: INTEGER
		do
			value := 3
			old := value -- E: SYNTAX-RESERVED
			print (value.out + "%N")
		end

end
