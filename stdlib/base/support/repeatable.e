note
	description: "[
		Objects that repeat an action over their own states: `repeat' calls `act' then
		`forth' until `after'. Descendants give `after' and `forth', and redefine `act'.
	]"

deferred class
	REPEATABLE

inherit
	ITERATION_CURSOR [REPEATABLE]

feature -- Access

	item: like Current
			-- The current object itself.
		do
			Result := Current
		end

feature -- Basic operations

	act
			-- Do the action of the current step.
		require
			not_after: not after
		do
		end

	repeat
			-- Call `act' and `forth' until `after'.
		do
			from
			until
				after
			loop
				act
				forth
			end
		end

end
