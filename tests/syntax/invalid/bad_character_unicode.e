note
	description: "A multiplication sign copied from a document is not an Eiffel operator."

class
	BAD_CHARACTER_UNICODE

create
	make

feature {NONE} -- Initialization

	make
			-- Compute an area.
		local
			area: INTEGER
		do
			area := 6 × 7 -- E: SYNTAX-LEXICAL
			print (area)
		end

end
