note
	description: "Stacks of bounded capacity, generic over any type."

class
	BOUNDED_STACK [G]

inherit
	ANY
		redefine
			out
		end

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Create an empty stack of capacity `n'.
		require
			n_positive: n > 0
		do
			create items.make (n)
			capacity := n
		ensure
			capacity_set: capacity = n
			empty: is_empty
		end

feature -- Access

	capacity: INTEGER
			-- Largest number of items.

	count: INTEGER
			-- Number of items.
		do
			Result := items.count
		end

	top: G
			-- The last item pushed.
		require
			not_empty: not is_empty
		do
			Result := items.last
		end

	top_or_default (default_value: like top): like top
			-- `top', or `default_value' when empty.
		do
			if is_empty then
				Result := default_value
			else
				Result := top
			end
		end

feature -- Status report

	is_empty: BOOLEAN
			-- Is the stack empty?
		do
			Result := count = 0
		end

	is_full: BOOLEAN
			-- Is the stack full?
		do
			Result := count = capacity
		end

feature -- Element change

	push (x: G)
			-- Put `x' on top.
		require
			not_full: not is_full
		do
			items.extend (x)
		ensure
			pushed: top = x
			one_more: count = old count + 1
		end

	pop
			-- Remove the top item.
		require
			not_empty: not is_empty
		do
			items.finish
			items.remove
		ensure
			one_less: count = old count - 1
		end

feature -- Conversion

	mapped (f: FUNCTION [G, G]): like Current
			-- A stack with `f' applied to every item.
		do
			create Result.make (capacity)
			across items as c loop
				Result.push (f.item ([c.item]))
			end
		end

	out: STRING
			-- Items from bottom to top.
		do
			create Result.make_empty
			across items as c loop
				if attached c.item as x then
					Result.append (x.out)
				end
				Result.append_character (' ')
			end
		end

feature {NONE} -- Implementation

	items: ARRAYED_LIST [G]
			-- The items, bottom first.

invariant
	count_in_bounds: 0 <= count and count <= capacity

end
