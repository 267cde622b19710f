note
	description: "[
		Structures whose items can be visited one after the other with an internal
		cursor (`start', `item', `forth', `after'). Searches and iteration routines
		(`has', `occurrences', `do_all', ...) use a separate cursor from `new_cursor'
		and leave the internal cursor where it is.
	]"

deferred class
	LINEAR [G]

inherit
	ACTIVE [G]

	ITERABLE [G]

feature -- Access

	index: INTEGER_32
			-- Position of the internal cursor.
		deferred
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			c: ITERATION_CURSOR [G]
		do
			from
				c := new_cursor
			until
				Result or c.after
			loop
				Result := same_item (c.item, v)
				c.forth
			end
		end

	index_of (v: G; i: INTEGER_32): INTEGER_32
			-- Position of the `i'-th occurrence of `v', or 0 if there is none.
			-- (Compared with `=' or `~' according to `object_comparison'.)
		require
			positive_occurrences: i > 0
		local
			c: ITERATION_CURSOR [G]
			position, found: INTEGER_32
		do
			from
				c := new_cursor
			until
				Result > 0 or c.after
			loop
				position := position + 1
				if same_item (c.item, v) then
					found := found + 1
					if found = i then
						Result := position
					end
				end
				c.forth
			end
		ensure
			non_negative_result: Result >= 0
		end

	occurrences (v: G): INTEGER_32
			-- <Precursor>
		do
			across Current as c loop
				if same_item (c.item, v) then
					Result := Result + 1
				end
			end
		end

feature -- Status report

	after: BOOLEAN
			-- Is the internal cursor past the last item?
		deferred
		end

	off: BOOLEAN
			-- Is there no current item?
		deferred
		end

	exhausted: BOOLEAN
			-- Has the internal cursor moved off the structure?
		do
			Result := off
		end

	readable: BOOLEAN
			-- Is there a current item to read?
		do
			Result := not off
		end

	writable: BOOLEAN
			-- Is there a current item to modify?
		do
			Result := not off
		end

feature -- Cursor movement

	start
			-- Move the internal cursor to the first item, if any.
		deferred
		end

	forth
			-- Move the internal cursor to the next item.
		require
			not_after: not after
		deferred
		end

	search (v: G)
			-- Move the internal cursor to the first position, at or after the current one,
			-- whose item is `v'; go `after' if there is none.
			-- (Compared with `=' or `~' according to `object_comparison'.)
		deferred
		ensure
			object_found: (not exhausted and object_comparison) implies v ~ item
			item_found: (not exhausted and not object_comparison) implies v = item
		end

feature -- Iteration

	do_all (action: PROCEDURE [TUPLE [G]])
			-- Apply `action' to every item, from first to last.
		do
			across Current as c loop
				action.call ([c.item])
			end
		end

	do_if (action: PROCEDURE [TUPLE [G]]; test: FUNCTION [TUPLE [G], BOOLEAN])
			-- Apply `action' to every item that satisfies `test', from first to last.
		do
			across Current as c loop
				if test.item ([c.item]) then
					action.call ([c.item])
				end
			end
		end

	there_exists (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for at least one item?
		local
			c: ITERATION_CURSOR [G]
		do
			from
				c := new_cursor
			until
				Result or c.after
			loop
				Result := test.item ([c.item])
				c.forth
			end
		end

	for_all (test: FUNCTION [TUPLE [G], BOOLEAN]): BOOLEAN
			-- Does `test' hold for every item?
		local
			c: ITERATION_CURSOR [G]
		do
			from
				Result := True
				c := new_cursor
			until
				not Result or c.after
			loop
				Result := test.item ([c.item])
				c.forth
			end
		end

feature -- Conversion

	linear_representation: LINEAR [G]
			-- The structure itself.
		do
			Result := Current
		end

feature {NONE} -- Implementation

	same_item (a, b: G): BOOLEAN
			-- Are `a' and `b' the same item for searches?
		do
			if object_comparison then
				Result := a ~ b
			else
				Result := a = b
			end
		end

end
