note
	description: "A philosopher who thinks and eats with the forks on both sides."

class
	PHILOSOPHER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_left, a_right: separate FORK; a_rounds: INTEGER)
			-- Philosopher `an_id' between `a_left' and `a_right' who will eat `a_rounds' times.
		require
			different_forks: a_left /= a_right
			positive_rounds: a_rounds > 0
		do
			id := an_id
			left_fork := a_left
			right_fork := a_right
			rounds := a_rounds
		ensure
			id_set: id = an_id
			rounds_set: rounds = a_rounds
		end

feature -- Access

	id: INTEGER
			-- Seat number.

	rounds: INTEGER
			-- Meals to have.

	times_eaten: INTEGER
			-- Meals had so far.

feature -- Basic operations

	live
			-- Think and eat until every meal is eaten.
		do
			from
			until
				times_eaten = rounds
			loop
				think
				eat (left_fork, right_fork)
			end
			separate left_fork as l, right_fork as r do
				print ("Philosopher " + id.out + " is done; forks " + l.id.out + " and " + r.id.out + " were used " + (l.use_count + r.use_count).out + " times%N")
			end
		end

feature {NONE} -- Implementation

	think
			-- Think a little.
		do
			print ("Philosopher " + id.out + " thinks%N")
		end

	eat (a_left, a_right: separate FORK)
			-- Eat with `a_left' and `a_right', both reserved at once.
		require
			hungry: times_eaten < rounds
		do
			a_left.pick_up (id)
			a_right.pick_up (id)
			times_eaten := times_eaten + 1
			print ("Philosopher " + id.out + " eats with forks " + a_left.id.out + " and " + a_right.id.out + "%N")
			a_left.put_down
			a_right.put_down
		ensure
			one_more_meal: times_eaten = old times_eaten + 1
			forks_back: not a_left.is_in_use and not a_right.is_in_use
		end

	left_fork: separate FORK
			-- Fork on the left.

	right_fork: separate FORK
			-- Fork on the right.

invariant
	not_overfed: times_eaten <= rounds

end
