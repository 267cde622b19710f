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
			separate cell as c do
				print (c.item.out + "%N")
		end

feature -- Access -- E: SYNTAX-END

	cell: separate CELL [INTEGER]

end
