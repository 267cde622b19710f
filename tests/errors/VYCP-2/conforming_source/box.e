class
	BOX

create
	make,
	from_integer,
	from_small

convert
	from_integer ({INTEGER}),
	from_small ({SMALL_BOX}) -- E: VYCP(2)@15

feature {NONE} -- Initialization

	make
			-- Empty box.
		do
		end

	from_integer (n: INTEGER)
			-- Box holding `n'.
		do
			value := n
		end

	from_small (b: SMALL_BOX)
			-- Box holding what `b' holds.
		do
			value := b.value
		end

feature -- Access

	value: INTEGER
			-- Content.

end
