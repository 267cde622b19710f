note
	description: "`~` (object equality) cannot be a feature's alias, nor can a word."

class
	ALIAS_NOT_AN_OPERATOR

feature -- Comparison

	same alias "~" (other: ALIAS_NOT_AN_OPERATOR): BOOLEAN -- E: SYNTAX
		do
			Result := True
		end

end
