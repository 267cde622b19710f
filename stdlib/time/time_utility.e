note
	description: "[
		Integer division rounded toward minus infinity (`div') and the remainder that goes
		with it (`mod', never negative for a positive divisor), as the time classes use them.
	]"

class
	TIME_UTILITY

feature -- Basic operations

	mod (i, j: INTEGER_32): INTEGER_32
			-- Remainder of `i' divided by `j', of the sign of `j'.
		require
			non_zero_divisor: j /= 0
		do
			Result := i \\ j
			if Result /= 0 and then (Result < 0) /= (j < 0) then
				Result := Result + j
			end
		ensure
			positive_for_positive_divisor: j > 0 implies (Result >= 0 and Result < j)
		end

	div (i, j: INTEGER_32): INTEGER_32
			-- Quotient of `i' by `j', rounded toward minus infinity.
		require
			non_zero_divisor: j /= 0
		do
			Result := (i - mod (i, j)) // j
		ensure
			definition: Result * j + mod (i, j) = i
		end

end
