note
	description: "A backquote is not an Eiffel character outside strings and comments."

class
	BAD_CHARACTER

create
	make

feature {NONE} -- Initialization

	make
			-- Compute a product.
		local
			n: INTEGER
		do
			n := `6 * 7` -- E: SYNTAX-LEXICAL
			print (n)
		end

end
