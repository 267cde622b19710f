class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use the operators.
		do
			print ((Current + 1).out + (Current - 1).out + (- Current).out + "%N")
		end

feature -- Access

	plus alias "+" (n: INTEGER): INTEGER
			-- 10 plus `n'.
		do
			Result := 10 + n
		end

	add alias "+" (n: INTEGER): INTEGER -- E: VFAV(1)
			-- Again 10 plus `n'.
		do
			Result := 10 + n
		end

	minus alias "-" (n: INTEGER): INTEGER
			-- 10 minus `n'.
		do
			Result := 10 - n
		end

	negated alias "-": INTEGER
			-- Minus 10.
		do
			Result := -10
		end

end
