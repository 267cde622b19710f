note
	description: "An expanded value whose `copy' is redefined: it marks the values it makes."

expanded class
	TALLY

inherit
	ANY
		redefine
			copy, is_equal, out
		end

feature -- Access

	value: INTEGER

	copied: BOOLEAN
			-- Was this value made by `copy'?

	out: STRING
		do
			Result := value.out
			if copied then
				Result.append (" (copied)")
			else
				Result.append (" (original)")
			end
		end

feature -- Change

	set (v: INTEGER)
		do
			value := v
		end

	copy (other: like Current)
		do
			value := other.value
			copied := True
		end

	is_equal (other: like Current): BOOLEAN
		do
			Result := value = other.value
		end

end
