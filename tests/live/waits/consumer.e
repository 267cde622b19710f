class CONSUMER

create
	make

feature

	cell: separate CELL

	make (c: separate CELL)
		do
			cell := c
		end

	run
		do
			consume (cell)
		end

	consume (c: separate CELL)
		require
			has_value: c.value > 0
		do
			print ("consumed " + c.value.out + "%N")
		end

end
