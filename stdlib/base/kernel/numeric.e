note
	description: "Objects with the arithmetic operations of a ring: `+', `-', `*', `/', unary `+' and `-'."

deferred class
	NUMERIC

feature -- Access

	one: like Current
			-- Neutral element for `*' and `/'.
		deferred
		end

	zero: like Current
			-- Neutral element for `+' and `-'.
		deferred
		end

feature -- Status report

	divisible (other: like Current): BOOLEAN
			-- May the current object be divided by `other'?
		deferred
		end

	exponentiable (other: NUMERIC): BOOLEAN
			-- May the current object be raised to the power `other'?
		deferred
		end

feature -- Basic operations

	plus alias "+" (other: like Current): like Current
			-- Sum with `other'.
		deferred
		end

	minus alias "-" (other: like Current): like Current
			-- Difference with `other'.
		deferred
		end

	product alias "*" (other: like Current): like Current
			-- Product by `other'.
		deferred
		end

	quotient alias "/" (other: like Current): like Current
			-- Division by `other'.
		require
			good_divisor: divisible (other)
		deferred
		end

	identity alias "+": like Current
			-- Unary plus.
		deferred
		end

	opposite alias "-": like Current
			-- Unary minus.
		deferred
		end

end
