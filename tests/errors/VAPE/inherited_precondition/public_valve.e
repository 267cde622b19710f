class
	PUBLIC_VALVE

inherit
	VALVE
		export
			{ANY} open
		redefine
			open
		end

feature -- Basic operations

	open
			-- Open, for every client; the inherited precondition still calls `is_safe'.
		do
		end

end
