note
	description: "Void was assigned to an entity of expanded type."

class
	VOID_ASSIGNED_TO_EXPANDED

inherit
	LANGUAGE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Void_assigned_to_expanded.
		do
			Result := {EXCEP_CONST}.Void_assigned_to_expanded
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Void assigned to expanded."
		end

end
