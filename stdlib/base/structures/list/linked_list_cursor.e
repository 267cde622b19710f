note
	description: "Remembered positions in a LINKED_LIST."

class
	LINKED_LIST_CURSOR [G]

inherit
	CURSOR

create
	make

feature {NONE} -- Initialization

	make (a_active: like active; a_after, a_before: BOOLEAN)
			-- Remember the cell `a_active' and whether the cursor was after or before.
		do
			active := a_active
			after := a_after
			before := a_before
		ensure
			active_set: active = a_active
			after_set: after = a_after
			before_set: before = a_before
		end

feature -- Access

	active: detachable BI_LINKABLE [G]
			-- The cell of the remembered item, if any.

	after: BOOLEAN
			-- Was the cursor after the last item?

	before: BOOLEAN
			-- Was the cursor before the first item?

end
