class
	LEAF

create
	make

feature {NONE} -- Initialization

	make (a_data: separate SPECIAL [INTEGER])
			-- A leaf over `a_data'.
		do
			data := a_data
		end

feature -- Access

	data: separate SPECIAL [INTEGER]
			-- The data, on the processor that created this leaf.

	total: INTEGER
			-- The last sum.

feature -- Basic operations

	compute
			-- Sum the data: needs the data's processor.
		do
			sum (data)
		end

	sum (a_data: separate SPECIAL [INTEGER])
			-- Count `a_data''s items.
		do
			total := a_data.count
		end

end
