note
	description: "An exception occurred while a rescue clause was running."

class
	RESCUE_FAILURE

inherit
	EIFFEL_RUNTIME_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Rescue_exception.
		do
			Result := {EXCEP_CONST}.Rescue_exception
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Exception in rescue clause."
		end

end
