class
	SHELF [G -> {PRINTABLE, SIZED} create make end, H -> PRINTABLE rename image as label end, K -> COMPARABLE]
		-- Several constraints, a creation constraint, renaming in a constraint.

feature -- Access

	total: INTEGER

	text: STRING
			-- Images appended so far.
		attribute
			create Result.make_empty
		end

feature -- Change

	fill (a_tag: H)
			-- Create an item, use features and operators of both constraints, and `a_tag' renamed.
		local
			l_item: G
		do
			create l_item.make
			total := l_item.size
			text.append (l_item + l_item)
			text.append (a_tag.label)
		end

	smaller (a, b: K): BOOLEAN
			-- An operator of the constraint COMPARABLE on K.
		do
			Result := a < b
		end

end
