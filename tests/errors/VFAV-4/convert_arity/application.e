class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use the operators.
		do
			amount := 5
			print ((- Current).amount.out + "%N")
		end

feature -- Access

	amount: INTEGER
			-- The value.

	negated alias "-" convert: APPLICATION -- E: VFAV(4)
			-- Unary minus.
		do
			create Result.make
			Result.set (- amount)
		end

	set (n: INTEGER)
			-- Set `amount' to `n'.
		do
			amount := n
		end

end
