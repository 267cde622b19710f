note
	description: "A total that accepts positive additions only."

class
	ACCUMULATOR

feature -- Access

	total: INTEGER
			-- Sum of the additions.

	checked_total (minimum: INTEGER): INTEGER
			-- `total', which must exceed `minimum' by more than 100.
		require
			large: total > minimum + 100
		do
			Result := total
		end

feature -- Element change

	add (n: INTEGER)
			-- Add `n'.
		require
			non_negative: n >= 0
		do
			total := total + n
		end

end
