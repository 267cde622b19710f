note
	description: "[
		Cells with a left and a right neighbour: the elements of two-way linked
		structures. Linking a cell to one side links the neighbour back.
	]"

class
	BI_LINKABLE [G]

inherit
	LINKABLE [G]
		redefine
			put_right,
			forget_right
		end

create
	put

feature -- Access

	left: detachable like Current
			-- The left neighbour, if any.

feature -- Element change

	put_right (other: detachable like Current)
			-- Make `other' the right neighbour, and the current cell its left neighbour.
		do
			right := other
			if attached other as o then
				o.simple_put_left (Current)
			end
		end

	put_left (other: detachable like Current)
			-- Make `other' the left neighbour, and the current cell its right neighbour.
		do
			left := other
			if attached other as o then
				o.simple_put_right (Current)
			end
		ensure
			chained: left = other
		end

	forget_right
			-- Remove the right neighbour, which forgets its left neighbour too.
		do
			if attached right as r then
				r.simple_forget_left
			end
			right := Void
		end

	forget_left
			-- Remove the left neighbour, which forgets its right neighbour too.
		do
			if attached left as l then
				l.simple_forget_right
			end
			left := Void
		ensure
			no_left: left = Void
		end

feature {BI_LINKABLE} -- Implementation

	simple_put_left (other: detachable like Current)
			-- Make `other' the left neighbour, without linking back.
		do
			left := other
		end

	simple_put_right (other: detachable like Current)
			-- Make `other' the right neighbour, without linking back.
		do
			right := other
		end

	simple_forget_left
			-- Remove the left neighbour, without unlinking back.
		do
			left := Void
		end

	simple_forget_right
			-- Remove the right neighbour, without unlinking back.
		do
			right := Void
		end

end
