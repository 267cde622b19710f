note
	description: "A check instruction found its assertion false."

class
	CHECK_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Check_instruction.
		do
			Result := {EXCEP_CONST}.Check_instruction
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Check instruction violated."
		end

end
