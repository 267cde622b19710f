note
	description: "Alias rules (VFAV): unary and binary `-` share an operator, a `convert` mark on a %
		%binary operator, one bracket and one parenthesis alias, a redefined alias, two inherited %
		%features with one alias told apart by a rename in the inherit clause."

class
	APPLICATION

inherit
	MONEY
		redefine
			item
		end

create
	make

feature {NONE} -- Initialization

	make
			-- Use every alias.
		do
			amount := 7
			print ((Current + 1).out + " " + (Current - 1).out + " " + (- Current).out + "%N")
			print (Current [2].out + "%N")
			show (3)
			print (((create {VECTOR}) + create {SUMMABLE}).generator + "%N")
		end

feature -- Access

	item alias "[]" (i: INTEGER): INTEGER
			-- `amount' times `i' plus one.
		do
			Result := amount * i + 1
		end

	show alias "()" (n: INTEGER)
			-- Print `n' times `amount'.
		do
			print ((n * amount).out + "%N")
		end

end
