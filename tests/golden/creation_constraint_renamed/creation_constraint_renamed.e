class
	CREATION_CONSTRAINT_RENAMED

create
	make

feature {NONE} -- Initialization

	make
			-- Create cells through a formal generic whose constraint renames `make' as `init'.
		local
			b: BOX [CELL]
		do
			create b
			print (b.fresh (7).value.out + "%N")
		end

end
