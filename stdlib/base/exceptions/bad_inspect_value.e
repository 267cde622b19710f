note
	description: "The value of an inspect instruction matched no branch and there is no else part."

class
	BAD_INSPECT_VALUE

inherit
	LANGUAGE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Incorrect_inspect_value.
		do
			Result := {EXCEP_CONST}.Incorrect_inspect_value
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Unmatched inspect value."
		end

end
