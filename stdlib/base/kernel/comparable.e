note
	description: "[
		Objects with a total order. Descendants give `<'; `<=', `>', `>=',
		`is_equal', `three_way_comparison', `max' and `min' follow from it.
	]"

deferred class
	COMPARABLE

inherit
	PART_COMPARABLE
		redefine
			is_less, is_less_equal, is_greater, is_greater_equal, is_equal
		end

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the current object less than `other'?
		deferred
		end

	is_less_equal alias "<=" (other: like Current): BOOLEAN
			-- Is the current object less than or equal to `other'?
		do
			Result := not (other < Current)
		end

	is_greater alias ">" (other: like Current): BOOLEAN
			-- Is the current object greater than `other'?
		do
			Result := other < Current
		end

	is_greater_equal alias ">=" (other: like Current): BOOLEAN
			-- Is the current object greater than or equal to `other'?
		do
			Result := not (Current < other)
		end

	is_equal (other: like Current): BOOLEAN
			-- Is neither object less than the other?
		do
			Result := not (Current < other) and not (other < Current)
		end

	three_way_comparison (other: like Current): INTEGER_32
			-- -1 if the current object is less than `other', 0 if equal, 1 if greater.
		do
			if Current < other then
				Result := -1
			elseif other < Current then
				Result := 1
			end
		ensure
			in_range: Result >= -1 and Result <= 1
		end

	max (other: like Current): like Current
			-- The greater of the current object and `other'.
		do
			if Current >= other then
				Result := Current
			else
				Result := other
			end
		end

	min (other: like Current): like Current
			-- The smaller of the current object and `other'.
		do
			if Current <= other then
				Result := Current
			else
				Result := other
			end
		end

end
