note
	description: "[
		A condition benchmark worker: `iterations' times, waits until the shared variable has
		its parity, then increments it.
	]"

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make (a_shared: separate SHARED; a_parity, an_iterations: INTEGER)
			-- Worker incrementing `a_shared' `an_iterations' times when its parity is `a_parity'.
		require
			valid_parity: a_parity = 0 or a_parity = 1
		do
			shared := a_shared
			parity := a_parity
			iterations := an_iterations
		end

feature -- Access

	parity: INTEGER
			-- Parity (0 even, 1 odd) the shared value must have before this worker increments it.

	iterations: INTEGER
			-- Increments to make.

	is_done: BOOLEAN
			-- Has every increment been made?

feature -- Basic operations

	live
			-- Make every increment, each when the shared value has the right parity.
		do
			across 1 |..| iterations as i loop
				change (shared)
			end
			is_done := True
		end

feature {NONE} -- Implementation

	change (s: separate SHARED)
			-- Once `s' has the parity of this worker, increment it.
		require
			parity: s.value \\ 2 = parity
		do
			s.increment
		end

	shared: separate SHARED
			-- The shared variable.

end
