note
	description: "Exceptions raised by the program itself: create one, `set_description', then `raise'."

class
	DEVELOPER_EXCEPTION

inherit
	EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Developer_exception.
		do
			Result := {EXCEP_CONST}.Developer_exception
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Developer exception."
		end

end
