note
	description: "The evaluation of an `old' expression failed; the exception is raised when the postcondition uses it."

class
	OLD_VIOLATION

inherit
	LANGUAGE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Old_exception.
		do
			Result := {EXCEP_CONST}.Old_exception
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Old expression evaluation failure."
		end

end
