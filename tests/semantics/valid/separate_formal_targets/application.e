note
	description: "Controlled calls on separate targets reached in less common ways (VUTA(3)): a tuple %
		%label passed as a separate argument, a conditional expression as an argument, and values of a %
		%formal generic type constrained by a separate type, controlled as arguments and in separate blocks."

class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Fill cells through a holder and through a tuple.
		local
			t: TUPLE [c: separate CELL]
			h: HOLDER [separate CELL]
		do
			create s1
			create s2
			t := [s1]
			fill (t.c, 1)
			fill (if t.c = s1 then s2 else s1 end, 2)
			create h.make (s1)
			h.bump
			show (s1)
			show (s2)
		end

	fill (c: separate CELL; v: INTEGER)
			-- Put `v' into `c'.
		do
			c.put (v)
		end

	show (c: separate CELL)
			-- Print the content of `c'.
		do
			print (c.count.out + "%N")
		end

	s1, s2: separate CELL
			-- Two cells on their own processors.

end
