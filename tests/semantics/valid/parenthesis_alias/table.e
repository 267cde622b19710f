class
	TABLE

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- A table of size `n'.
		do
			size := n
		end

feature -- Access

	size: INTEGER
			-- Rows and columns.

	item alias "()" (i, j: INTEGER): INTEGER
			-- The product of `i' and `j'.
		require
			in_range: i <= size and j <= size
		do
			Result := i * j
		end

end
