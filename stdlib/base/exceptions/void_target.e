note
	description: "A feature was called on a Void target."

class
	VOID_TARGET

inherit
	LANGUAGE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Void_call_target.
		do
			Result := {EXCEP_CONST}.Void_call_target
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Feature call on void target."
		end

end
