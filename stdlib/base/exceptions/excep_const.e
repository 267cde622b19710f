note
	description: "Codes of the predefined kinds of exceptions, as EXCEPTION.code and EXCEPTIONS give them."

class
	EXCEP_CONST

feature -- Access

	Void_call_target: INTEGER_32 = 1
			-- Call on a Void target.

	No_more_memory: INTEGER_32 = 2
			-- Memory exhausted.

	Precondition: INTEGER_32 = 3
			-- Violated precondition.

	Postcondition: INTEGER_32 = 4
			-- Violated postcondition.

	Floating_point_exception: INTEGER_32 = 5
			-- Floating-point error.

	Class_invariant: INTEGER_32 = 6
			-- Violated class invariant.

	Check_instruction: INTEGER_32 = 7
			-- Violated check instruction.

	Routine_failure: INTEGER_32 = 8
			-- A routine failed.

	Incorrect_inspect_value: INTEGER_32 = 9
			-- Inspect value matched no branch and there is no else part.

	Loop_variant: INTEGER_32 = 10
			-- Loop variant not decreased (or negative).

	Loop_invariant: INTEGER_32 = 11
			-- Violated loop invariant.

	Signal_exception: INTEGER_32 = 12
			-- Operating system signal.

	Eiffel_runtime_panic: INTEGER_32 = 13
			-- Run-time panic.

	Rescue_exception: INTEGER_32 = 14
			-- Exception in a rescue clause.

	Out_of_memory: INTEGER_32 = 15
			-- Out of memory (cannot be ignored).

	Resumption_failed: INTEGER_32 = 16
			-- A retry did not succeed.

	Create_on_deferred: INTEGER_32 = 17
			-- Creation of an object of a deferred class.

	External_exception: INTEGER_32 = 18
			-- Error in an external routine.

	Void_assigned_to_expanded: INTEGER_32 = 19
			-- Void assigned to an expanded entity.

	Exception_in_signal_handler: INTEGER_32 = 20
			-- Exception in a signal handler.

	Io_exception: INTEGER_32 = 21
			-- Input or output error.

	Operating_system_exception: INTEGER_32 = 22
			-- Operating system error.

	Retrieve_exception: INTEGER_32 = 23
			-- Error while retrieving stored objects.

	Developer_exception: INTEGER_32 = 24
			-- Exception raised by the program itself.

	Eiffel_runtime_fatal_error: INTEGER_32 = 25
			-- Fatal run-time error.

	Dollar_applied_to_melted_feature: INTEGER_32 = 26
			-- Address taken of a feature that has none.

	Runtime_io_exception: INTEGER_32 = 27
			-- Input or output error raised by the run time.

	Com_exception: INTEGER_32 = 28
			-- COM error.

	Runtime_check_exception: INTEGER_32 = 29
			-- Violated run-time check.

	Old_exception: INTEGER_32 = 30
			-- Exception while evaluating an `old' expression.

	Serialization_exception: INTEGER_32 = 31
			-- Serialization error.

	Number_of_codes: INTEGER_32 = 31
			-- Number of codes.

feature -- Status report

	valid_code (c: INTEGER_32): BOOLEAN
			-- Is `c' the code of a predefined kind of exception?
		do
			Result := c >= 1 and c <= Number_of_codes
		end

end
