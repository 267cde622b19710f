note
	description: "[
		Agents standing for a call to a function returning a RESULT_TYPE.
		`f.item ([a, b])' (or `f (a, b)') calls it and returns its result;
		`call' and `apply' keep the result in `last_result'.
	]"

class
	FUNCTION [OPEN_ARGS -> detachable TUPLE create default_create end, RESULT_TYPE]

inherit
	ROUTINE [OPEN_ARGS]
		redefine
			is_equal,
			copy
		end

create {NONE}

feature -- Access

	last_result: detachable RESULT_TYPE
			-- Result of the last `call' or `apply', if any.

	item alias "()" (args: detachable separate OPEN_ARGS): RESULT_TYPE
			-- Result of calling the function with `args' as open operands.
		require
			valid_operands: valid_operands (args)
		external
			"Python"
		end

	flexible_item (a: detachable separate TUPLE): RESULT_TYPE
			-- Result of calling the function with the items of `a' as open operands;
			-- `a' need not be of type OPEN_ARGS, only suitable for `valid_operands'.
		require
			valid_operands: valid_operands (a)
		external
			"Python"
		end

feature -- Basic operations

	call (args: detachable separate OPEN_ARGS)
			-- Call the function with `args' and keep its result in `last_result'.
		do
			last_result := item (args)
		end

	apply
			-- Call the function with `operands' and keep its result in `last_result'.
		do
			last_result := item (operands)
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current agent and `other' stand for the same call, with the same `last_result'?
		do
			Result := Precursor (other) and then last_result ~ other.last_result
		end

feature -- Duplication

	copy (other: like Current)
			-- Stand for the same call as `other', with the same `last_result'.
		do
			if other /= Current then
				Precursor (other)
				last_result := other.last_result
			end
		end

feature -- Removal

	clear_last_result
			-- Forget `last_result'.
		local
			l_default: detachable RESULT_TYPE
		do
			last_result := l_default
		end

end
