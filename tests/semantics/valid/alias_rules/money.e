note
	description: "Operators, a converting one among them, and a bracket alias."

class
	MONEY

feature -- Access

	amount: INTEGER
			-- The value.

	plus alias "+" convert (n: INTEGER): INTEGER
			-- `amount' plus `n'.
		do
			Result := amount + n
		end

	minus alias "-" (n: INTEGER): INTEGER
			-- `amount' minus `n'.
		do
			Result := amount - n
		end

	negated alias "-": INTEGER
			-- Minus `amount'.
		do
			Result := - amount
		end

	item alias "[]" (i: INTEGER): INTEGER
			-- `amount' times `i'.
		do
			Result := amount * i
		end

end
