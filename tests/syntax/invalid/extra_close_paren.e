note
	description: "One closing parenthesis too many."

class
	EXTRA_CLOSE_PAREN

create
	make

feature {NONE} -- Initialization

	make
			-- Print a product.
		local
			a, b: INTEGER
		do
			a := 2
			b := 3
			print ((a * b).out)) -- E: SYNTAX
		end

end
