class
	BOX [G]

create
	make,
	make_empty

feature {NONE} -- Initialization

	make (v: G)
		do
			item := v
			has_item := True
		end

	make_empty
		do
		end

feature -- Access

	item: detachable G
			-- Void (or the default of an expanded G) until set: `make_empty' leaves it unset.

	has_item: BOOLEAN

	image: STRING
			-- `item' printed as its own class prints it, and that class.
		do
			if attached item as i then
				Result := i.out + " " + i.generator
			else
				Result := "Void"
			end
		end

	mapped (f: FUNCTION [G, G]): BOX [G]
		do
			check attached item as i then
				create Result.make (f (i))
			end
		end

	replaced (v: G): like Current
		do
			Result := twin
			Result.set (v)
		end

feature -- Change

	set (v: G)
		do
			item := v
		end

end
