note
	description: "Philosophers eat with two separate forks, reserved together."

class
	PHILOSOPHER

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER; a_left, a_right: separate FORK; a_rounds: INTEGER)
			-- Philosopher `n' between `a_left' and `a_right'.
		require
			valid_rounds: a_rounds >= 0
		do
			id := n
			left := a_left
			right := a_right
			rounds := a_rounds
		end

feature -- Access

	id, rounds, meals: INTEGER
	left, right: separate FORK

feature -- Basic operations

	live
			-- Eat `rounds' times.
		do
			from
			until
				meals >= rounds
			loop
				eat (left, right)
				think
			end
		end

	eat (l, r: separate FORK)
			-- Eat with forks `l' and `r', both reserved for the whole call.
		do
			l.use
			r.use
			meals := meals + 1
		end

	think
			-- Think a while, then inspect both forks at once in a separate block.
		do
			separate left as l, right as r do
				if l.uses > 1_000_000 or r.uses > 1_000_000 then
					print ("busy forks%N")
				end
			end
		end

end
