class
	BOX [G]

inherit
	ANCESTOR

create
	make

convert
	to_ancestor: {ANCESTOR} -- E: VYCQ(3)@16

feature {NONE} -- Initialization

	make
			-- Empty box.
		do
		end

feature -- Access

	to_ancestor: ANCESTOR
			-- Current, seen as an ANCESTOR.
		do
			Result := Current
		end

end
