note
	description: "[
		Access to the exception being handled (`last_exception', for rescue clauses)
		and to the handling of kinds of exceptions.
	]"
	implementation: "[
		`last_exception', `ignore', `catch' and `is_ignored' are `external "Python"':
		the runtime keeps, per processor, the exception being handled and the set of ignored kinds.
	]"

class
	EXCEPTION_MANAGER

feature -- Access

	last_exception: detachable EXCEPTION
			-- The exception being handled by the current rescue clause, if any.
		external
			"Python"
		end

	exception_from_code (a_code: INTEGER_32): detachable EXCEPTION
			-- New exception of the kind coded `a_code', if it is a predefined kind.
		do
			inspect a_code
			when 1 then
				create {VOID_TARGET} Result
			when 2, 15 then
				create {NO_MORE_MEMORY} Result
			when 3 then
				create {PRECONDITION_VIOLATION} Result
			when 4 then
				create {POSTCONDITION_VIOLATION} Result
			when 5 then
				create {FLOATING_POINT_FAILURE} Result
			when 6 then
				create {INVARIANT_VIOLATION} Result
			when 7 then
				create {CHECK_VIOLATION} Result
			when 8 then
				create {ROUTINE_FAILURE} Result
			when 9 then
				create {BAD_INSPECT_VALUE} Result
			when 10 then
				create {VARIANT_VIOLATION} Result
			when 11 then
				create {LOOP_INVARIANT_VIOLATION} Result
			when 12 then
				create {OPERATING_SYSTEM_SIGNAL_FAILURE} Result
			when 14 then
				create {RESCUE_FAILURE} Result
			when 16 then
				create {RESUMPTION_FAILURE} Result
			when 17 then
				create {CREATE_ON_DEFERRED} Result
			when 18 then
				create {EXTERNAL_FAILURE} Result
			when 19 then
				create {VOID_ASSIGNED_TO_EXPANDED} Result
			when 21, 27 then
				create {IO_FAILURE} Result
			when 22 then
				create {OPERATING_SYSTEM_FAILURE} Result
			when 24 then
				create {DEVELOPER_EXCEPTION} Result
			when 30 then
				create {OLD_VIOLATION} Result
			else
			end
		end

feature -- Status report

	is_ignorable (a_exception: TYPE [detachable EXCEPTION]): BOOLEAN
			-- May exceptions of type `a_exception' be ignored?
		do
			Result := not a_exception.is_conforming_to ({detachable ASSERTION_VIOLATION})
		end

	is_raisable (a_exception: TYPE [detachable EXCEPTION]): BOOLEAN
			-- May exceptions of type `a_exception' be raised by a program?
		do
			Result := True
		end

	is_ignored (a_exception: TYPE [detachable EXCEPTION]): BOOLEAN
			-- Are exceptions of type `a_exception' ignored?
		external
			"Python"
		end

	is_caught (a_exception: TYPE [detachable EXCEPTION]): BOOLEAN
			-- Are exceptions of type `a_exception' caught (the default)?
		do
			Result := not is_ignored (a_exception)
		end

feature -- Status setting

	ignore (a_exception: TYPE [detachable EXCEPTION])
			-- Ignore exceptions of type `a_exception' from now on.
		require
			is_ignorable: is_ignorable (a_exception)
		external
			"Python"
		end

	catch (a_exception: TYPE [detachable EXCEPTION])
			-- Catch exceptions of type `a_exception' from now on (the default).
		external
			"Python"
		end

	set_is_ignored (a_exception: TYPE [detachable EXCEPTION]; a_ignored: BOOLEAN)
			-- Ignore exceptions of type `a_exception' if `a_ignored', catch them otherwise.
		require
			is_ignorable: a_ignored implies is_ignorable (a_exception)
		do
			if a_ignored then
				ignore (a_exception)
			else
				catch (a_exception)
			end
		end

feature -- Raise

	raise (a_exception: EXCEPTION)
			-- Raise `a_exception'.
		require
			is_raisable: a_exception.is_raisable
		do
			a_exception.raise
		end

end
