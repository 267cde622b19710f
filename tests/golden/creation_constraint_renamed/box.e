class
	BOX [G -> CELL rename make as init end create init end]

feature -- Access

	fresh (n: INTEGER): G
			-- A new G made by CELL's `make', called `init' here.
		do
			create Result.init (n)
		end

end
