note
	description: "[
		Finite linear structures that can also be traversed backwards (`finish',
		`back', `before') and extended at the end.
	]"

deferred class
	SEQUENCE [G]

inherit
	LINEAR [G]

feature -- Status report

	before: BOOLEAN
			-- Is the internal cursor before the first item?
		deferred
		end

	off: BOOLEAN
			-- Is the internal cursor `before' or `after'?
		do
			Result := before or after
		end

feature -- Cursor movement

	finish
			-- Move the internal cursor to the last item, if any.
		deferred
		end

	back
			-- Move the internal cursor to the previous item.
		require
			not_before: not before
		deferred
		end

	search (v: G)
			-- <Precursor>
		do
			if before and not is_empty then
				forth
			end
			from
			until
				off or else same_item (item, v)
			loop
				forth
			end
		end

feature -- Element change

	force (v: G)
			-- Add `v' at the end.
		require
			extendible: extendible
		do
			extend (v)
		end

	append (s: SEQUENCE [G])
			-- Add the items of `s', in order, at the end.
		require
			extendible: extendible
		local
			l: SEQUENCE [G]
		do
			l := s
			if s = Current then
				l := twin
			end
			across l as c loop
				extend (c.item)
			end
		end

end
