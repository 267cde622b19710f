note
	description: "Adds up the squares of a range of numbers, on its own processor."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (an_id, a_lower, an_upper: INTEGER)
			-- Worker `an_id' for the numbers `a_lower' to `an_upper'.
		require
			valid_range: 1 <= a_lower and a_lower <= an_upper
		do
			id := an_id
			lower := a_lower
			upper := an_upper
		ensure
			not_done: not is_done
		end

feature -- Access

	id: INTEGER
			-- Worker number.

	lower: INTEGER
			-- First number of the range.

	upper: INTEGER
			-- Last number of the range.

	sum: INTEGER_64
			-- Sum of the squares of the range, once computed.
		require
			computed: is_done
		attribute
		end

feature -- Status report

	is_done: BOOLEAN
			-- Has the sum been computed?

feature -- Basic operations

	compute
			-- Sum the squares of `lower' to `upper'.
		require
			not_yet: not is_done
		local
			l_sum: INTEGER_64
		do
			across lower |..| upper as i loop
				l_sum := l_sum + i.item.to_integer_64 * i.item.to_integer_64
			end
			sum := l_sum
			is_done := True
			print ("Worker " + id.out + ": squares of " + lower.out + ".." + upper.out + " add up to " + sum.out + "%N")
		ensure
			done: is_done
			positive: sum > 0
		end

end
