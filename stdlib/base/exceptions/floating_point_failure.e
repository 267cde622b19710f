note
	description: "Floating-point errors."

class
	FLOATING_POINT_FAILURE

inherit
	HARDWARE_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Floating_point_exception.
		do
			Result := {EXCEP_CONST}.Floating_point_exception
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Floating point exception."
		end

end
