note
	description: "An object's class invariant was false on entry to or exit from a qualified call."

class
	INVARIANT_VIOLATION

inherit
	ASSERTION_VIOLATION
		redefine
			code, internal_meaning
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception: {EXCEP_CONST}.Class_invariant.
		do
			Result := {EXCEP_CONST}.Class_invariant
		end

feature -- Access

	is_entry: BOOLEAN
			-- Was the invariant checked on entry to the call (rather than on exit)?

feature {EXCEPTION_MANAGER} -- Element change

	set_is_entry (b: BOOLEAN)
			-- Set `is_entry'.
		do
			is_entry := b
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning'.
		do
			Result := "Class invariant violated."
		end

end
