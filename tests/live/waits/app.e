class APP

inherit
	ARGUMENTS

create
	make

feature

	make
			-- Start a consumer that waits until the cell holds a value; give it one after a
			-- pause (`pause` milliseconds: the first argument, else 1500), or never (0: a deadlock).
		local
			c: separate CELL
			w: separate CONSUMER
			pause: INTEGER
		do
			pause := 1500
			if argument_count > 0 then
				pause := argument (1).to_integer
			end
			create c
			create w.make (c)
			start (w)
			if pause > 0 then
				(create {EXECUTION_ENVIRONMENT}).sleep (pause.to_integer_64 * 1_000_000)
				fill (c)
			end
		end

	start (w: separate CONSUMER)
		do
			w.run
		end

	fill (c: separate CELL)
		do
			c.set (1)
		end

end
