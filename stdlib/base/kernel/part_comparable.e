note
	description: "Objects that may be compared by a partial order: `<' is given, the other relations follow."

deferred class
	PART_COMPARABLE

feature -- Comparison

	is_less alias "<" (other: like Current): BOOLEAN
			-- Is the current object less than `other'?
		deferred
		end

	is_less_equal alias "<=" (other: like Current): BOOLEAN
			-- Is the current object less than or equal to `other'?
		do
			Result := Current < other or is_equal (other)
		end

	is_greater alias ">" (other: like Current): BOOLEAN
			-- Is the current object greater than `other'?
		do
			Result := other < Current
		end

	is_greater_equal alias ">=" (other: like Current): BOOLEAN
			-- Is the current object greater than or equal to `other'?
		do
			Result := other <= Current
		end

end
