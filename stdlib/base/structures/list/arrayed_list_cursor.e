note
	description: "Remembered positions in an ARRAYED_LIST."

class
	ARRAYED_LIST_CURSOR

inherit
	CURSOR

create
	make

feature {NONE} -- Initialization

	make (i: INTEGER_32)
			-- Remember position `i'.
		do
			index := i
		ensure
			index_set: index = i
		end

feature -- Access

	index: INTEGER_32
			-- The remembered position.

end
