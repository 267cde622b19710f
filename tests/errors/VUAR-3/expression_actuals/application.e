class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Pass traitors.
		local
			c: separate CELL
		do
			create c
			run (c)
		end

	run (c: separate CELL)
			-- Pass non-separate data to `c'.
		local
			d: DATA
			t: TUPLE [item: DATA]
		do
			create d
			t := [d]
			c.keep (if c.count > 0 then d else d end) -- E: VUAR(3)
			c.keep (inspect c.count when 1 then d else d end) -- E: VUAR(3)
			c.keep (t.item) -- E: VUAR(3)
		end

end
