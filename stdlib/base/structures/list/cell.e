note
	description: "Cells holding one value, which may be read with `item' and changed with `put'."

class
	CELL [G]

create
	put,
	make

feature {NONE} -- Initialization

	make (v: G)
			-- Hold `v'.
		do
			item := v
		ensure
			item_set: item = v
		end

feature -- Access

	item: G
			-- The value held.

feature -- Element change

	put, replace (v: G)
			-- Hold `v' from now on.
		do
			item := v
		ensure
			item_inserted: item = v
		end

end
