note
	description: "Cells that also refer to a right neighbour: the elements of one-way linked structures."

class
	LINKABLE [G]

inherit
	CELL [G]

create
	put

feature -- Access

	right: detachable like Current
			-- The right neighbour, if any.

feature -- Element change

	put_right (other: detachable like Current)
			-- Make `other' the right neighbour.
		do
			right := other
		ensure
			chained: right = other
		end

	forget_right
			-- Remove the right neighbour.
		do
			right := Void
		ensure
			no_right: right = Void
		end

end
