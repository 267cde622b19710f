note
	description: "Operating system signals received by the program."

class
	OPERATING_SYSTEM_SIGNAL_FAILURE

inherit
	OPERATING_SYSTEM_EXCEPTION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Signal_exception.
		do
			Result := {EXCEP_CONST}.Signal_exception
		end

feature -- Access

	signal_code: INTEGER_32
			-- Number of the signal.

feature {EXCEPTION_MANAGER} -- Element change

	set_signal_code (a_code: INTEGER_32)
			-- Set `signal_code'.
		do
			signal_code := a_code
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Operating system signal."
		end

end
