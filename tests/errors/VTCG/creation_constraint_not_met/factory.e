class
	FACTORY [G -> PRODUCT create make end]

feature -- Basic operations

	produced (n: INTEGER): G
			-- A new item made with `make'.
		do
			create Result.make
		end

end
