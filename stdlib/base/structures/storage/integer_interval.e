note
	description: "[
		Intervals of consecutive integers `lower' .. `upper' (empty when `upper' < `lower'),
		as made by `a |..| b'. An interval is its own index set: `item (i)' is `i'.
	]"

class
	INTEGER_INTERVAL

inherit
	FINITE [INTEGER_32]

	READABLE_INDEXABLE [INTEGER_32]
		redefine
			index_set
		end

create
	make

feature {NONE} -- Initialization

	make (min_index, max_index: INTEGER_32)
			-- Make the interval `min_index' .. `max_index' (empty, 1 .. 0, if `min_index' > `max_index').
		do
			if min_index <= max_index then
				lower_internal := min_index
				upper_internal := max_index
			else
				lower_internal := 1
				upper_internal := 0
			end
		ensure
			set_if_non_empty: min_index <= max_index implies (lower = min_index and upper = max_index)
			empty_if_not_in_order: min_index > max_index implies is_empty
		end

feature -- Access

	lower: INTEGER_32
			-- Smallest value.
		do
			Result := lower_internal
		end

	upper: INTEGER_32
			-- Largest value.
		do
			Result := upper_internal
		end

	lower_defined: BOOLEAN = True
			-- Is there a lower bound? (Yes.)

	upper_defined: BOOLEAN = True
			-- Is there an upper bound? (Yes.)

	item alias "[]", at alias "@" (i: INTEGER_32): INTEGER_32
			-- The value at index `i', which is `i'.
		do
			Result := i
		end

	has, valid_index (v: INTEGER_32): BOOLEAN
			-- Is `v' in the interval?
		do
			Result := lower <= v and v <= upper
		end

	index_set: INTEGER_INTERVAL
			-- The interval itself.
		do
			Result := Current
		end

feature -- Measurement

	count, capacity: INTEGER_32
			-- Number of values.
		do
			Result := upper - lower + 1
		end

	occurrences (v: INTEGER_32): INTEGER_32
			-- 1 if `v' is in the interval, otherwise 0.
		do
			if has (v) then
				Result := 1
			end
		end

feature -- Element change

	extend, put (v: INTEGER_32)
			-- Stretch the interval down to `v' or up to `v' (an empty interval 1 .. 0
			-- becomes 1 .. `v' for a positive `v').
		do
			if v < lower then
				lower_internal := v
			elseif v > upper then
				upper_internal := v
			end
		ensure
			extended_down: lower = (old lower).min (v)
			extended_up: upper = (old upper).max (v)
		end

	resize (min_index, max_index: INTEGER_32)
			-- Stretch the interval to include `min_index' .. `max_index'.
		do
			lower_internal := min_index.min (lower)
			upper_internal := max_index.max (upper)
		end

	resize_exactly (min_index, max_index: INTEGER_32)
			-- Make the interval `min_index' .. `max_index' (empty, 1 .. 0, if `min_index' > `max_index').
		do
			make (min_index, max_index)
		end

	grow (i: INTEGER_32)
			-- Stretch the interval upwards to hold at least `i' values.
		do
			if count < i then
				upper_internal := lower + i - 1
			end
		end

feature -- Removal

	wipe_out
			-- Make the interval empty (1 .. 0).
		do
			lower_internal := 1
			upper_internal := 0
		ensure
			empty: is_empty
		end

feature -- Conversion

	as_array: ARRAY [INTEGER_32]
			-- An array indexed by the interval, each value at its own index.
		local
			i: INTEGER_32
		do
			create Result.make_filled (0, lower, upper)
			from
				i := lower
			until
				i > upper
			loop
				Result.put (i, i)
				i := i + 1
			end
		ensure
			same_lower: Result.lower = lower
			same_upper: Result.upper = upper
		end

	linear_representation: ARRAYED_LIST [INTEGER_32]
			-- The values, in increasing order.
		local
			i: INTEGER_32
		do
			create Result.make (count)
			from
				i := lower
			until
				i > upper
			loop
				Result.extend (i)
				i := i + 1
			end
		end

	subinterval (start_pos, end_pos: INTEGER_32): INTEGER_INTERVAL
			-- The interval `start_pos' .. `end_pos'.
		do
			create Result.make (start_pos, end_pos)
		end

feature -- Iteration

	do_all (action: PROCEDURE [TUPLE [INTEGER_32]])
			-- Apply `action' to every value, in increasing order.
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper
			loop
				action.call ([i])
				i := i + 1
			end
		end

	do_if (action: PROCEDURE [TUPLE [INTEGER_32]]; test: FUNCTION [TUPLE [INTEGER_32], BOOLEAN])
			-- Apply `action' to every value that satisfies `test', in increasing order.
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper
			loop
				if test.item ([i]) then
					action.call ([i])
				end
				i := i + 1
			end
		end

	for_all (condition: FUNCTION [TUPLE [INTEGER_32], BOOLEAN]): BOOLEAN
			-- Does `condition' hold for every value?
		local
			i: INTEGER_32
		do
			from
				Result := True
				i := lower
			until
				i > upper or not Result
			loop
				Result := condition.item ([i])
				i := i + 1
			end
		end

	exists, there_exists (condition: FUNCTION [TUPLE [INTEGER_32], BOOLEAN]): BOOLEAN
			-- Does `condition' hold for at least one value?
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper or Result
			loop
				Result := condition.item ([i])
				i := i + 1
			end
		end

	exists1 (condition: FUNCTION [TUPLE [INTEGER_32], BOOLEAN]): BOOLEAN
			-- Does `condition' hold for exactly one value?
		do
			Result := hold_count (condition) = 1
		end

	hold_count (condition: FUNCTION [TUPLE [INTEGER_32], BOOLEAN]): INTEGER_32
			-- Number of values for which `condition' holds.
		local
			i: INTEGER_32
		do
			from
				i := lower
			until
				i > upper
			loop
				if condition.item ([i]) then
					Result := Result + 1
				end
				i := i + 1
			end
		end

feature {INTEGER_INTERVAL} -- Implementation

	lower_internal: INTEGER_32
			-- Smallest value.

	upper_internal: INTEGER_32
			-- Largest value.

invariant
	count_definition: count = upper - lower + 1
	non_negative_count: count >= 0

end
