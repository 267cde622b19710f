class
	MERGEABLE

feature -- Operations

	merged alias "+" (other: MERGEABLE): MERGEABLE
			-- Merge with `other'.
		do
			Result := other
		end

end
