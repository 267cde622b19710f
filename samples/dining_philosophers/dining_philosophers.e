note
	description: "[
		Dining philosophers: each philosopher is a processor and eats by reserving both of
		its forks at once, so no philosopher holds one fork while waiting for the other and
		the table cannot deadlock.
	]"

class
	DINING_PHILOSOPHERS

create
	make

feature {NONE} -- Initialization

	make
			-- Lay the forks, seat the philosophers and let them dine.
		local
			l_forks: ARRAYED_LIST [separate FORK]
			l_fork: separate FORK
			l_philosopher: separate PHILOSOPHER
			i: INTEGER
		do
			create l_forks.make (Philosopher_count)
			from
				i := 1
			until
				i > Philosopher_count
			loop
				create l_fork.make (i)
				l_forks.extend (l_fork)
				i := i + 1
			end
			from
				i := 1
			until
				i > Philosopher_count
			loop
				create l_philosopher.make (i, l_forks.i_th (i), l_forks.i_th (i \\ Philosopher_count + 1), Round_count)
				launch (l_philosopher)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	launch (a_philosopher: separate PHILOSOPHER)
			-- Let `a_philosopher' start dining.
		do
			a_philosopher.live
		end

	Philosopher_count: INTEGER = 5
			-- Number of philosophers, and of forks.

	Round_count: INTEGER = 3
			-- Meals each philosopher has.

end
