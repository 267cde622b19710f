note
	description: "A philosopher who thinks, then eats with the forks on both sides, a few times."

class
	PHILOSOPHER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_left, a_right: separate FORK; a_rounds: INTEGER)
			-- Philosopher `an_id' between `a_left' and `a_right', who will eat `a_rounds' times.
		require
			valid_seat: an_id > 0
			two_forks: a_left /= a_right
			positive_rounds: a_rounds > 0
		do
			id := an_id
			left_fork := a_left
			right_fork := a_right
			round_count := a_rounds
		ensure
			id_set: id = an_id
			hungry: times_eaten = 0
		end

feature -- Access

	id: INTEGER
			-- Seat number.

	round_count: INTEGER
			-- Meals to have.

	times_eaten: INTEGER
			-- Meals had so far.

feature -- Basic operations

	live
			-- Think and eat until every meal is eaten.
		do
			from
			until
				times_eaten = round_count
			loop
				think
				eat (left_fork, right_fork)
			end
			print ("Philosopher " + id.out + " is done after " + times_eaten.out + " meals%N")
		end

feature {NONE} -- Implementation

	think
			-- Think a little.
		do
			print ("Philosopher " + id.out + " thinks (round " + (times_eaten + 1).out + ")%N")
			(create {EXECUTION_ENVIRONMENT}).sleep (Thinking_time)
		end

	eat (a_left, a_right: separate FORK)
			-- Eat with `a_left' and `a_right', both reserved at once.
		require
			still_hungry: times_eaten < round_count
		do
			a_left.pick_up (id)
			a_right.pick_up (id)
			times_eaten := times_eaten + 1
			print ("Philosopher " + id.out + " eats with forks " + a_left.id.out + " and " + a_right.id.out + " (round " + times_eaten.out + ")%N")
			(create {EXECUTION_ENVIRONMENT}).sleep (Eating_time)
			a_left.put_down (id)
			a_right.put_down (id)
		ensure
			one_more_meal: times_eaten = old times_eaten + 1
			forks_back: not a_left.is_in_use and not a_right.is_in_use
		end

	left_fork: separate FORK
			-- Fork on the left.

	right_fork: separate FORK
			-- Fork on the right.

	Thinking_time: INTEGER_64 = 2_000_000
			-- Time spent thinking, in nanoseconds.

	Eating_time: INTEGER_64 = 3_000_000
			-- Time spent eating, in nanoseconds.

invariant
	not_overfed: times_eaten <= round_count

end
