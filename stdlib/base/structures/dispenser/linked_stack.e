note
	description: "Stacks made of linked cells, from the top item down."

class
	LINKED_STACK [G]

inherit
	STACK [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make
			-- Make an empty stack.
		do
		ensure
			is_empty: is_empty
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a stack by pushing the items of `other' in order (the last one on top).
		do
			make
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- The top item.
		do
			check attached top as t then
				Result := t.item
			end
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			p: detachable LINKABLE [G]
		do
			from
				p := top
			until
				Result or p = Void
			loop
				if attached p as pp then
					Result := same_item (pp.item, v)
					p := pp.right
				end
			end
		end

feature -- Measurement

	count: INTEGER_32
			-- <Precursor>

	occurrences (v: G): INTEGER_32
			-- <Precursor>
		local
			p: detachable LINKABLE [G]
		do
			from
				p := top
			until
				p = Void
			loop
				if attached p as pp then
					if same_item (pp.item, v) then
						Result := Result + 1
					end
					p := pp.right
				end
			end
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current stack and `other' hold the same items in the same order,
			-- with the same comparison criterion?
		local
			p, q: detachable LINKABLE [G]
		do
			if count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					p := top
					q := other.top
				until
					not Result or p = Void or q = Void
				loop
					if attached p as pp and attached q as qq then
						Result := same_item (pp.item, qq.item)
						p := pp.right
						q := qq.right
					end
				end
			end
		end

feature -- Status report

	prunable: BOOLEAN
			-- May items be removed? (Yes.)
		do
			Result := True
		end

feature -- Element change

	extend, put, force (v: G)
			-- Push `v' on top.
		local
			c: LINKABLE [G]
		do
			create c.put (v)
			c.put_right (top)
			top := c
			count := count + 1
		end

	replace (v: G)
			-- Put `v' in place of the top item.
		do
			if attached top as t then
				t.put (v)
			end
		end

feature -- Removal

	remove
			-- Pop the top item.
		do
			if attached top as t then
				top := t.right
				t.forget_right
				count := count - 1
			end
		end

	wipe_out
			-- Remove every item.
		do
			top := Void
			count := 0
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, from the top to the bottom.
		local
			p: detachable LINKABLE [G]
		do
			from
				create Result.make (count)
				p := top
			until
				p = Void
			loop
				if attached p as pp then
					Result.extend (pp.item)
					p := pp.right
				end
			end
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items of `other', in cells of its own.
		local
			items: ARRAYED_LIST [G]
		do
			if other /= Current then
				standard_copy (other)
				items := other.linear_representation
				wipe_out
				from
					items.finish
				until
					items.before
				loop
					extend (items.item)
					items.back
				end
			end
		end

feature {LINKED_STACK} -- Implementation

	top: detachable LINKABLE [G]
			-- Cell of the top item.

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

invariant
	empty_constraint: is_empty = (top = Void)

end
