note
	description: "Philosophers around a table, each on its own processor, sharing one fork with each neighbour."

class
	DINING_PHILOSOPHERS

create
	make

feature {NONE} -- Initialization

	make
			-- Lay `Philosopher_count' forks, seat as many philosophers and let them dine.
		local
			i: INTEGER
			l_fork: separate FORK
			l_philosopher: separate PHILOSOPHER
		do
			create forks.make (Philosopher_count)
			from
				i := 1
			until
				i > Philosopher_count
			loop
				create l_fork.make (i)
				forks.extend (l_fork)
				i := i + 1
			end
			create philosophers.make (Philosopher_count)
			from
				i := 1
			until
				i > Philosopher_count
			loop
				create l_philosopher.make (i, forks.i_th (i), forks.i_th (i \\ Philosopher_count + 1), Round_count)
				philosophers.extend (l_philosopher)
				i := i + 1
			end
			across philosophers as c loop
				launch (c.item)
			end
		end

feature {NONE} -- Implementation

	launch (a_philosopher: separate PHILOSOPHER)
			-- Let `a_philosopher' start dining.
		do
			a_philosopher.live
		end

	forks: ARRAYED_LIST [separate FORK]
			-- The forks, fork `i' between philosophers `i' and `i - 1'.

	philosophers: ARRAYED_LIST [separate PHILOSOPHER]
			-- The philosophers, in seating order.

	Philosopher_count: INTEGER = 5
			-- Number of philosophers (and of forks).

	Round_count: INTEGER = 3
			-- Meals each philosopher has.

end
