class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Call on uncontrolled separate targets.
		local
			t: TUPLE [c: separate CELL]
			h: HOLDER [separate CELL]
		do
			create s1.make
			create s2.make
			t := [s1]
			t.c.put (1) -- E: VUTA(3)
			;(if t.c = s1 then s1 else s2 end).put (2) -- E: VUTA(3)
			;(inspect t.count when 1 then s1 else s2 end).put (3) -- E: VUTA(3)
			create h.make (s1)
		end

	s1, s2: separate CELL
			-- Two cells on their own processors.

end
