note
	description: "Errors reported by an operating system call."

class
	OPERATING_SYSTEM_FAILURE

inherit
	OPERATING_SYSTEM_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Operating_system_exception.
		do
			Result := {EXCEP_CONST}.Operating_system_exception
		end

feature -- Access

	error_code: INTEGER_32
			-- Error number given by the operating system or the host.

feature {EXCEPTION_MANAGER} -- Element change

	set_error_code (a_code: INTEGER_32)
			-- Set `error_code'.
		do
			error_code := a_code
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Operating system error."
		end

end
