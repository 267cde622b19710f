note
	description: "A word that is not an operator keyword cannot be a feature's alias."

class
	ALIAS_A_WORD

feature -- Comparison

	same alias "equals" (other: ALIAS_A_WORD): BOOLEAN -- E: SYNTAX
		do
			Result := True
		end

end
