note
	description: "A loop invariant was false."

class
	LOOP_INVARIANT_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Loop_invariant.
		do
			Result := {EXCEP_CONST}.Loop_invariant
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Loop invariant violated."
		end

end
