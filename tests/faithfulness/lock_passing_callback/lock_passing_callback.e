class
	LOCK_PASSING_CALLBACK

create
	make

feature

	make
			-- Two diners share two plates; each takes both, in the same order.
		local
			a, b: separate PLATE
			d: separate DINER
		do
			create a.make ('A')
			create b.make ('B')
			across 1 |..| 2 as i loop
				create d.make (i.item, a, b)
				start (d)
			end
		end

	start (d: separate DINER)
		do
			d.dine (5)
		end

end
