class
	BOX [G]

create
	make,
	from_small

convert
	from_small ({SMALL_BOX [G]}) -- E: VYCP(3)@15

feature {NONE} -- Initialization

	make
			-- Empty box.
		do
		end

	from_small (b: SMALL_BOX [G])
			-- Box holding what `b' holds.
		do
			item := b.item
		end

feature -- Access

	item: detachable G
			-- Content.

end
