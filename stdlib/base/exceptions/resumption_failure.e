note
	description: "A retry could not resume the routine."

class
	RESUMPTION_FAILURE

inherit
	EIFFEL_RUNTIME_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Resumption_failed.
		do
			Result := {EXCEP_CONST}.Resumption_failed
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Resumption attempt failed."
		end

end
