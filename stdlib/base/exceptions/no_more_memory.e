note
	description: "Memory was exhausted."

class
	NO_MORE_MEMORY

inherit
	EIFFEL_RUNTIME_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.No_more_memory.
		do
			Result := {EXCEP_CONST}.No_more_memory
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "No more memory."
		end

end
