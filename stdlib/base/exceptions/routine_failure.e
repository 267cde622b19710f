note
	description: "A routine failed: an exception reached the end of its rescue clause (or it has none)."

class
	ROUTINE_FAILURE

inherit
	LANGUAGE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Routine_failure.
		do
			Result := {EXCEP_CONST}.Routine_failure
		end

feature -- Access

	routine_name: detachable STRING_8
			-- Name of the routine that failed.

	class_name: detachable STRING_8
			-- Name of the class of the routine that failed.

feature {EXCEPTION_MANAGER} -- Element change

	set_routine_name (a_name: detachable STRING_8)
			-- Set `routine_name'.
		do
			routine_name := a_name
		end

	set_class_name (a_name: detachable STRING_8)
			-- Set `class_name'.
		do
			class_name := a_name
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Routine failure."
		end

end
