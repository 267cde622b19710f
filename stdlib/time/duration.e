note
	description: "[
		Durations: amounts of time that can be added, subtracted and negated, ordered where
		they can be compared. EiffelTime's DURATION, with GROUP_ELEMENT's operations.
	]"

deferred class
	DURATION

inherit
	PART_COMPARABLE

feature -- Basic operations

	plus alias "+" (other: like Current): like Current
			-- Sum of Current and `other'.
		deferred
		end

	minus alias "-" (other: like Current): like Current
			-- Difference of Current and `other'.
		deferred
		end

	opposite alias "-": like Current
			-- Current negated.
		deferred
		end

end
