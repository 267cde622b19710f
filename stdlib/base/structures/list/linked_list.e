note
	description: "[
		Lists made of linked cells: fast insertion and removal at the cursor and at
		both ends, access by index by walking from the nearer end. The cursor stays
		with its item (or `before' / `after') when items are added elsewhere.
	]"

class
	LINKED_LIST [G]

inherit
	DYNAMIC_LIST [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_from_iterable

feature {NONE} -- Initialization

	make
			-- Make an empty list.
		do
			index := 0
		ensure
			is_before: before
			is_empty: is_empty
		end

	make_from_iterable (other: ITERABLE [G])
			-- Make a list of the items of `other', in order.
		do
			make
			across other as c loop
				extend (c.item)
			end
		end

feature -- Access

	item: G
			-- <Precursor>
		do
			check attached active as a then
				Result := a.item
			end
		end

	i_th alias "[]", at alias "@" (i: INTEGER_32): G assign put_i_th
			-- <Precursor>
		do
			check attached cell_at (i) as c then
				Result := c.item
			end
		end

	index: INTEGER_32
			-- <Precursor>

	cursor: LINKED_LIST_CURSOR [G]
			-- <Precursor>
		do
			create Result.make (active, after, before)
		end

	new_cursor: LINKED_LIST_ITERATION_CURSOR [G]
			-- <Precursor>
		do
			create Result.make (Current)
			Result.start
		end

feature -- Measurement

	count: INTEGER_32
			-- <Precursor>

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current list and `other' hold the same items, with the same comparison criterion?
		local
			p, q: detachable BI_LINKABLE [G]
		do
			if other = Current then
				Result := True
			elseif count = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					p := first_element
					q := other.first_element
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

	valid_cursor (p: CURSOR): BOOLEAN
			-- <Precursor>
		local
			c: detachable BI_LINKABLE [G]
		do
			if attached {LINKED_LIST_CURSOR [G]} p as lc then
				if lc.before or lc.after then
					Result := True
				else
					from
						c := first_element
					until
						Result or c = Void
					loop
						if attached c as cc then
							Result := cc = lc.active
							c := cc.right
						end
					end
				end
			end
		end

	full: BOOLEAN = False
			-- Is there no room for more items? (Never.)

feature -- Cursor movement

	start
			-- <Precursor>
		do
			index := 1
			active := first_element
		ensure then
			empty_convention: is_empty implies after
		end

	finish
			-- <Precursor>
		do
			index := count
			active := last_element
		ensure then
			empty_convention: is_empty implies before
		end

	forth
			-- <Precursor>
		do
			if index = 0 then
				active := first_element
			elseif attached active as a then
				active := a.right
			end
			index := index + 1
		end

	back
			-- <Precursor>
		do
			if index = count + 1 then
				active := last_element
			elseif attached active as a then
				active := a.left
			end
			index := index - 1
		end

	go_i_th (i: INTEGER_32)
			-- <Precursor>
		do
			index := i
			active := cell_at (i)
		end

	go_to (p: CURSOR)
			-- <Precursor>
		local
			c: detachable BI_LINKABLE [G]
			i: INTEGER_32
		do
			if attached {LINKED_LIST_CURSOR [G]} p as lc then
				if lc.before then
					go_i_th (0)
				elseif lc.after then
					go_i_th (count + 1)
				else
					from
						c := first_element
						i := 1
					until
						c = Void or else c = lc.active
					loop
						if attached c as cc then
							c := cc.right
						end
						i := i + 1
					end
					go_i_th (i)
				end
			end
		end

feature -- Element change

	extend (v: G)
			-- Add `v' at the end; the cursor stays on its item (or `before' / `after').
		do
			append_cell (v)
		end

	put_front (v: G)
			-- <Precursor>
		local
			c: BI_LINKABLE [G]
		do
			create c.put (v)
			c.put_right (first_element)
			first_element := c
			if last_element = Void then
				last_element := c
			end
			if index > 0 then
				index := index + 1
			end
			count := count + 1
		end

	put_left (v: G)
			-- <Precursor>
		local
			c: BI_LINKABLE [G]
		do
			if after then
				append_cell (v)
			elseif attached active as a then
				create c.put (v)
				if attached a.left as l then
					l.put_right (c)
				else
					first_element := c
				end
				c.put_right (a)
				index := index + 1
				count := count + 1
			end
		end

	put_right (v: G)
			-- <Precursor>
		local
			c: BI_LINKABLE [G]
		do
			if before then
				put_front (v)
			elseif attached active as a then
				create c.put (v)
				if attached a.right as r then
					c.put_right (r)
				else
					last_element := c
				end
				a.put_right (c)
				count := count + 1
			end
		end

	replace (v: G)
			-- <Precursor>
		do
			if attached active as a then
				a.put (v)
			end
		end

	put_i_th (v: G; i: INTEGER_32)
			-- <Precursor>
		do
			if attached cell_at (i) as c then
				c.put (v)
			end
		end

feature -- Removal

	remove
			-- Remove the current item; the cursor moves to the next one (or `after').
		local
			r: detachable BI_LINKABLE [G]
		do
			if attached active as a then
				r := a.right
				unlink (a)
				active := r
			end
		ensure then
			same_index: index = old index
		end

	remove_left
			-- <Precursor>
		local
			c: detachable BI_LINKABLE [G]
		do
			if after then
				c := last_element
			elseif attached active as a then
				c := a.left
			end
			if attached c as cc then
				unlink (cc)
			end
			index := index - 1
		end

	remove_right
			-- <Precursor>
		local
			c: detachable BI_LINKABLE [G]
		do
			if before then
				c := first_element
			elseif attached active as a then
				c := a.right
			end
			if attached c as cc then
				unlink (cc)
			end
		end

	wipe_out
			-- <Precursor>
		do
			first_element := Void
			last_element := Void
			active := Void
			count := 0
			index := 0
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the items and cursor position of `other', in cells of its own.
		local
			l_index: INTEGER_32
		do
			if other /= Current then
				standard_copy (other)
				l_index := other.index
				wipe_out
				across other as c loop
					append_cell (c.item)
				end
				go_i_th (l_index)
			end
		end

	duplicate (n: INTEGER_32): like Current
			-- <Precursor>
		local
			p: detachable BI_LINKABLE [G]
			i: INTEGER_32
		do
			create Result.make
			from
				p := active
			until
				i = n or p = Void
			loop
				if attached p as pp then
					Result.extend (pp.item)
					p := pp.right
				end
				i := i + 1
			end
		end

feature {LINKED_LIST, LINKED_LIST_ITERATION_CURSOR} -- Implementation

	first_element: detachable BI_LINKABLE [G]
			-- The cell of the first item.

	last_element: detachable BI_LINKABLE [G]
			-- The cell of the last item.

	active: detachable BI_LINKABLE [G]
			-- The cell of the current item (Void when `off').

feature {NONE} -- Implementation

	cell_at (i: INTEGER_32): detachable BI_LINKABLE [G]
			-- The cell of the `i'-th item (Void if there is none), reached from the nearer end.
		local
			j: INTEGER_32
		do
			if 1 <= i and i <= count then
				if i <= count // 2 + 1 then
					from
						Result := first_element
						j := 1
					until
						j = i
					loop
						if attached Result as r then
							Result := r.right
						end
						j := j + 1
					end
				else
					from
						Result := last_element
						j := count
					until
						j = i
					loop
						if attached Result as r then
							Result := r.left
						end
						j := j - 1
					end
				end
			end
		end

	append_cell (v: G)
			-- Add a cell for `v' at the end; the cursor stays on its item (or `before' / `after').
		local
			c: BI_LINKABLE [G]
		do
			create c.put (v)
			if attached last_element as l then
				l.put_right (c)
			else
				first_element := c
			end
			last_element := c
			if index = count + 1 then
				index := index + 1
			end
			count := count + 1
		end

	unlink (a: BI_LINKABLE [G])
			-- Take the cell `a' out of the chain.
		local
			l, r: detachable BI_LINKABLE [G]
		do
			l := a.left
			r := a.right
			a.forget_left
			a.forget_right
			if attached l as ll then
				ll.put_right (r)
			else
				first_element := r
			end
			if r = Void then
				last_element := l
			end
			count := count - 1
		end

invariant
	empty_constraint: is_empty implies (first_element = Void and last_element = Void)
	active_when_on_item: (not off) = (active /= Void)

end
