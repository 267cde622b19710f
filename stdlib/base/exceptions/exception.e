note
	description: "[
		Exceptions as objects: every failure (contract violation, call on Void, routine
		failure, developer exception, error of the host) is an instance of a descendant.
		A rescue clause can inspect the current one through EXCEPTION_MANAGER.last_exception.
	]"
	implementation: "[
		`raise' is `external "Python"': the runtime throws the object and fills
		`recipient_name', `type_name', `line_number' and `trace' (through the setters
		exported to EXCEPTION_MANAGER) when it catches it.
	]"

class
	EXCEPTION

inherit
	ANY
		redefine
			out
		end

create
	default_create,
	make_with_tag_and_trace

feature {NONE} -- Initialization

	make_with_tag_and_trace (a_tag, a_trace_string: READABLE_STRING_GENERAL)
			-- Exception with description `a_tag' and trace `a_trace_string'.
		do
			set_description (a_tag)
			create internal_trace.make_from_string_general (a_trace_string)
		end

feature -- Raise

	raise
			-- Raise the current exception.
		require
			is_raisable: is_raisable
		external
			"Python"
		end

feature -- Access

	code: INTEGER_32
			-- Code of the exception (see EXCEP_CONST); 0 for exceptions of no predefined kind.
		do
			Result := 0
		end

	meaning: STRING_8
			-- Short text saying what kind of exception this is.
		do
			Result := internal_meaning
		end

	tag: IMMUTABLE_STRING_32
			-- `description', or empty if there is none.
		do
			if attached description as l_description then
				create Result.make_from_string_general (l_description)
			else
				create Result.make_empty
			end
		end

	message: detachable STRING_8
			-- `description' as a STRING_8, if any.
		do
			if attached description as l_description then
				Result := l_description.as_string_8
			end
		end

	description: detachable READABLE_STRING_32
			-- Details of the exception: the violated assertion's tag, the developer's text, ...

	trace: detachable STRING_32
			-- Call stack at the point the exception was raised, as text.
		do
			Result := internal_trace
		end

	exception_trace: detachable STRING_8
			-- `trace' as a STRING_8.
		do
			if attached trace as l_trace then
				Result := l_trace.as_string_8
			end
		end

	frozen original: EXCEPTION
			-- The exception at the origin of the current one: following routine failures
			-- back to the exception that started them.
		do
			Result := Current
			if attached {ROUTINE_FAILURE} Current and attached throwing_exception as l_cause then
				Result := l_cause.original
			end
		end

	frozen cause: EXCEPTION
			-- The exception that caused the current one (itself if none).
		do
			if attached throwing_exception as l_cause then
				Result := l_cause
			else
				Result := Current
			end
		end

	frozen recipient_name: detachable STRING_8
			-- Name of the routine whose execution the exception interrupted.

	frozen type_name: detachable STRING_8
			-- Name of the class of that routine.

	frozen line_number: INTEGER_32
			-- Source line where the exception was raised (0 if unknown).

feature -- Status settings

	set_message (a_message: detachable READABLE_STRING_GENERAL)
			-- Make `a_message' the `description'.
		do
			set_description (a_message)
		end

	set_description (a_description: detachable READABLE_STRING_GENERAL)
			-- Make `a_description' the `description'.
		do
			if attached a_description as l_description then
				description := l_description.as_string_32.twin
			else
				description := Void
			end
		end

feature -- Status report

	frozen is_ignorable: BOOLEAN
			-- May the exception be ignored?
		do
			Result := not attached {ASSERTION_VIOLATION} Current
		end

	frozen is_raisable: BOOLEAN
			-- May the exception be raised by `raise'?
		do
			Result := True
		end

	frozen is_ignored: BOOLEAN
			-- Is the exception ignored (see EXCEPTION_MANAGER.ignore)?
		do
			Result := (create {EXCEPTION_MANAGER_FACTORY}).exception_manager.is_ignored (generating_type)
		end

	frozen is_caught: BOOLEAN
			-- Is the exception caught (the default)?
		do
			Result := not is_ignored
		end

feature -- Output

	out: STRING_8
			-- Class name, code, meaning and description.
		do
			Result := generator + " (" + code.out + "): " + meaning
			if attached description as l_description then
				Result.append (" ")
				Result.append (l_description.as_string_8)
			end
		end

feature {EXCEPTION} -- Access

	frozen throwing_exception: detachable EXCEPTION
			-- The exception that caused the current one, if any.

feature {EXCEPTION_MANAGER} -- Implementation

	frozen set_throwing_exception (a_exception: detachable EXCEPTION)
			-- Make `a_exception' the cause of the current exception.
		do
			throwing_exception := a_exception
		end

	frozen set_recipient_name (a_name: detachable STRING_8)
			-- Set `recipient_name'.
		do
			recipient_name := a_name
		end

	frozen set_type_name (a_type: detachable STRING_8)
			-- Set `type_name'.
		do
			type_name := a_type
		end

	frozen set_line_number (a_number: INTEGER_32)
			-- Set `line_number'.
		do
			line_number := a_number
		end

	frozen set_exception_trace (a_trace: detachable READABLE_STRING_GENERAL)
			-- Set `trace'.
		do
			if attached a_trace as l_trace then
				create internal_trace.make_from_string_general (l_trace)
			else
				internal_trace := Void
			end
		end

feature {NONE} -- Implementation

	internal_meaning: STRING_8
			-- Text of `meaning' for this kind of exception.
		do
			Result := "General exception."
		end

	internal_trace: detachable STRING_32
			-- Storage for `trace'.

end
