note
	description: "A separate block without its `end'."

class
	MISSING_END_SEPARATE

create
	make

feature {NONE} -- Initialization

	make
			-- Read a separate cell.
		do
			create cell.put (3)
			separate cell as c do -- E: SYNTAX-END@4
				print (c.item.out + "%N")
		end

feature -- Access

	cell: separate CELL [INTEGER]

end
