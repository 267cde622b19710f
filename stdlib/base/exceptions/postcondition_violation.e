note
	description: "A routine ended with its postcondition false."

class
	POSTCONDITION_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Postcondition.
		do
			Result := {EXCEP_CONST}.Postcondition
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Postcondition violated."
		end

end
