note
	description: "Holds a value of a formal generic type constrained by a separate type."

class
	HOLDER [G -> separate CELL]

create
	make

feature {NONE} -- Initialization

	make (x: G)
			-- Keep `x' and put 5 into it (the argument is controlled).
		do
			item := x
			x.put (5)
		end

feature -- Element change

	bump
			-- Add one to the content of `item' (controlled by a separate block).
		do
			separate item as c do
				c.put (c.count + 1)
			end
		end

feature -- Access

	item: G
			-- The cell kept.

end
