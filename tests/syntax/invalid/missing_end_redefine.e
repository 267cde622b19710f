note
	description: "A parent's redefine clause not closed by `end' before the creation clause."

class
	MISSING_END_REDEFINE

inherit
	ANY
		redefine -- E: SYNTAX-END@3
			out

create
	make

feature {NONE} -- Initialization

	make
		do
		end

feature -- Output

	out: STRING
		do
			Result := "x"
		end

end
