note
	description: "Queues made of linked cells, from the oldest item to the newest."

class
	LINKED_QUEUE [G]

inherit
	QUEUE [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make
			-- Make an empty queue.
		do
		ensure
			is_empty: is_empty
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a queue of the items of `other', the first one oldest.
		do
			make
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- The oldest item.
		do
			check attached oldest as o then
				Result := o.item
			end
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			p: detachable LINKABLE [G]
		do
			from
				p := oldest
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
				p := oldest
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
			-- Do the current queue and `other' hold the same items in the same order,
			-- with the same comparison criterion?
		local
			p, q: detachable LINKABLE [G]
		do
			if count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					p := oldest
					q := other.oldest
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
			-- Add `v' as the newest item.
		local
			c: LINKABLE [G]
		do
			create c.put (v)
			if attached newest as n then
				n.put_right (c)
			else
				oldest := c
			end
			newest := c
			count := count + 1
		end

	replace (v: G)
			-- Put `v' in place of the oldest item.
		do
			if attached oldest as o then
				o.put (v)
			end
		end

feature -- Removal

	remove
			-- Remove the oldest item.
		do
			if attached oldest as o then
				oldest := o.right
				o.forget_right
				if oldest = Void then
					newest := Void
				end
				count := count - 1
			end
		end

	wipe_out
			-- Remove every item.
		do
			oldest := Void
			newest := Void
			count := 0
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, from the oldest to the newest.
		local
			p: detachable LINKABLE [G]
		do
			from
				create Result.make (count)
				p := oldest
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
			p: detachable LINKABLE [G]
		do
			if other /= Current then
				standard_copy (other)
				p := other.oldest
				wipe_out
				from
				until
					p = Void
				loop
					if attached p as pp then
						extend (pp.item)
						p := pp.right
					end
				end
			end
		end

feature {LINKED_QUEUE} -- Implementation

	oldest: detachable LINKABLE [G]
			-- Cell of the oldest item.

	newest: detachable LINKABLE [G]
			-- Cell of the newest item.

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
	empty_constraint: is_empty = (oldest = Void)

end
