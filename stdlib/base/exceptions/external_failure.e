note
	description: "An external routine failed; for `external %"Python%"' routines, the Python exception's text is the description."

class
	EXTERNAL_FAILURE

inherit
	EIFFEL_RUNTIME_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.External_exception.
		do
			Result := {EXCEP_CONST}.External_exception
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "External event."
		end

end
