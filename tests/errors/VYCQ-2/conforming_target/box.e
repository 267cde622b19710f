class
	BOX

inherit
	ANCESTOR

create
	make

convert
	to_integer: {INTEGER},
	to_ancestor: {ANCESTOR} -- E: VYCQ(2)@16

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Box holding `n'.
		do
			value := n
		end

feature -- Access

	value: INTEGER
			-- Content.

	to_integer: INTEGER
			-- `value'.
		do
			Result := value
		end

	to_ancestor: ANCESTOR
			-- Current, seen as an ANCESTOR.
		do
			Result := Current
		end

end
