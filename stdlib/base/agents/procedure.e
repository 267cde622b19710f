note
	description: "[
		Agents standing for a call to a procedure. `p.call ([a, b])' (or `p (a, b)')
		calls it with open operands `a' and `b'.
	]"

class
	PROCEDURE [OPEN_ARGS -> detachable TUPLE create default_create end]

inherit
	ROUTINE [OPEN_ARGS]
		rename
			call as call alias "()"
		end

create {NONE}

feature -- Basic operations

	call alias "()" (args: detachable separate OPEN_ARGS)
			-- <Precursor>
		external
			"Python"
		end

	apply
			-- <Precursor>
		do
			call (operands)
		end

end
