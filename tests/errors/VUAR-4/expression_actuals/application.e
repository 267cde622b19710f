class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Pass expanded values with references.
		local
			c: separate CELL
		do
			create c
			run (c)
		end

	run (c: separate CELL)
			-- Pass `PAIR' values to `c'.
		local
			p, q: PAIR
			t: TUPLE [item: PAIR]
		do
			p.set ("left")
			q.set ("right")
			t := [p]
			c.keep (if c.count > 0 then p else q end) -- E: VUAR(4)
			c.keep (inspect c.count when 1 then p else q end) -- E: VUAR(4)
			c.keep (t.item) -- E: VUAR(4)
		end

end
