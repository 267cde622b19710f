note
	description: "A loop variant became negative or did not decrease."

class
	VARIANT_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Loop_variant.
		do
			Result := {EXCEP_CONST}.Loop_variant
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Loop variant violated."
		end

end
