note
	description: "The sum of the squares of a range of numbers, posted as a job."

class
	CHUNK_TASK

create
	make

feature {NONE} -- Initialization

	make (a_board: separate JOB_BOARD; a_total: separate ACCUMULATOR; a_lower, a_upper: INTEGER)
			-- Task summing the squares of `a_lower' to `a_upper' into `a_total', posted on `a_board'.
		require
			open_board: not a_board.is_closed
			valid_range: a_lower <= a_upper
		do
			lower := a_lower
			upper := a_upper
			total := a_total
			a_board.post (agent compute)
		end

feature -- Access

	lower: INTEGER
			-- First number of the range.

	upper: INTEGER
			-- Last number of the range.

feature -- Basic operations

	compute
			-- Sum the squares of the range and add the sum to `total'.
		local
			l_sum: INTEGER
		do
			across lower |..| upper as i loop
				l_sum := l_sum + i.item * i.item
			end
			contribute (total, l_sum)
		end

feature {NONE} -- Implementation

	contribute (a_total: separate ACCUMULATOR; a_sum: INTEGER)
			-- Add `a_sum' to `a_total'.
		do
			a_total.add (a_sum)
		end

	total: separate ACCUMULATOR
			-- Where the partial sum goes.

end
