note
	description: "A routine was called with its precondition false."

class
	PRECONDITION_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Precondition.
		do
			Result := {EXCEP_CONST}.Precondition
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Precondition violated."
		end

end
