note
	description: "A generic parent of the root class: only the root type itself must be non-generic."

deferred class
	BOX [G]

feature -- Access

	item: detachable G
			-- The content.

	put (x: G)
			-- Keep `x'.
		do
			item := x
		ensure
			kept: item = x
		end

end
