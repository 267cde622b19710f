note
	description: "[
		The classic interface to exceptions: raising developer exceptions and querying the
		last exception from a rescue clause. Inherit it or create it.
	]"
	implementation: "Plain Eiffel over EXCEPTION_MANAGER.last_exception; `die' is `external %"Python%"'."

class
	EXCEPTIONS

inherit
	EXCEP_CONST

	EXCEPTION_MANAGER_FACTORY

feature -- Status report

	meaning (except: INTEGER_32): detachable STRING_8
			-- Text describing the kind of exception coded `except'.
		do
			if attached exception_manager.exception_from_code (except) as l_exception then
				Result := l_exception.meaning
			end
		end

	exception: INTEGER_32
			-- Code of the last exception.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.code
			end
		end

	original_exception: INTEGER_32
			-- Code of the exception at the origin of the last one.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.code
			end
		end

	assertion_violation: BOOLEAN
			-- Was the last exception originally a violated assertion?
		do
			Result := attached exception_manager.last_exception as l_exception and then
				attached {ASSERTION_VIOLATION} l_exception.original
		end

	is_developer_exception: BOOLEAN
			-- Was the last exception originally raised by the program (a developer exception)?
		do
			Result := attached exception_manager.last_exception as l_exception and then
				attached {DEVELOPER_EXCEPTION} l_exception.original
		end

	is_developer_exception_of_name (name: detachable READABLE_STRING_8): BOOLEAN
			-- Was the last exception originally a developer exception named `name'?
		do
			if is_developer_exception then
				if attached developer_exception_name as l_name and attached name as l_given then
					Result := l_name.same_string (l_given)
				else
					Result := developer_exception_name = Void and name = Void
				end
			end
		end

	developer_exception_name: detachable STRING_8
			-- Name of the last developer exception.
		require
			applicable: is_developer_exception
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.message
			end
		end

	is_signal: BOOLEAN
			-- Was the last exception originally an operating system signal?
		do
			Result := attached exception_manager.last_exception as l_exception and then
				attached {OPERATING_SYSTEM_SIGNAL_FAILURE} l_exception.original
		end

	is_system_exception: BOOLEAN
			-- Was the last exception originally an operating system error?
		do
			Result := attached exception_manager.last_exception as l_exception and then
				(attached {OPERATING_SYSTEM_FAILURE} l_exception.original or
				attached {EXTERNAL_FAILURE} l_exception.original)
		end

	tag_name: detachable STRING_8
			-- Tag of the last violated assertion, or text of the last exception.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.message
			end
		end

	original_tag_name: detachable STRING_8
			-- Tag or text of the exception at the origin of the last one.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.message
			end
		end

	recipient_name: detachable STRING_8
			-- Name of the routine the last exception interrupted.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.recipient_name
			end
		end

	original_recipient_name: detachable STRING_8
			-- Name of the routine the original exception interrupted.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.recipient_name
			end
		end

	class_name: detachable STRING_8
			-- Name of the class of the routine the last exception interrupted.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.type_name
			end
		end

	original_class_name: detachable STRING_8
			-- Name of the class of the routine the original exception interrupted.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.type_name
			end
		end

	exception_trace: detachable STRING_8
			-- Call stack of the last exception, as text.
		do
			if attached exception_manager.last_exception as l_exception then
				Result := l_exception.original.exception_trace
			end
		end

feature -- Status setting

	catch (code: INTEGER_32)
			-- Catch exceptions of code `code' (the default).
		do
			if attached exception_manager.exception_from_code (code) as l_exception then
				exception_manager.catch (l_exception.generating_type)
			end
		end

	ignore (code: INTEGER_32)
			-- Ignore exceptions of code `code' from now on.
		do
			if attached exception_manager.exception_from_code (code) as l_exception then
				if exception_manager.is_ignorable (l_exception.generating_type) then
					exception_manager.ignore (l_exception.generating_type)
				end
			end
		end

	message_on_failure
			-- Print the exception trace if the program fails (the default).
		do
		end

	no_message_on_failure
			-- Do not print the exception trace if the program fails.
		do
		end

feature -- Basic operations

	raise (name: detachable READABLE_STRING_8)
			-- Raise a developer exception named `name'.
		local
			l_exception: DEVELOPER_EXCEPTION
		do
			create l_exception
			l_exception.set_description (name)
			l_exception.raise
		end

	die (code: INTEGER_32)
			-- End the program at once with exit status `code', without an exception.
		external
			"Python"
		end

end
