note
	description: "[
		Agents: objects standing for a call to a routine, made by `agent' expressions.
		Some operands (the target and arguments) are closed (given when the agent was
		made); the open ones are passed, as a tuple of type OPEN_ARGS, to `call'.
	]"
	implementation: "[
		Agents are made by the compiler, never with `create'. Every feature whose result
		depends on the routine and its closed operands is `external "Python"' (bound by
		class and feature name); the runtime keeps, for each agent, the routine, its
		target (when closed), its closed operands and the positions of the open ones.
	]"

deferred class
	ROUTINE [OPEN_ARGS -> detachable TUPLE create default_create end]

inherit
	HASHABLE
		redefine
			is_equal,
			copy
		end

feature -- Access

	operands: detachable OPEN_ARGS
			-- Open operands set by `set_operands', used by `apply'.
		external
			"Python"
		end

	target: detachable ANY
			-- Target of the call, if it is closed or already set in `operands'.
		external
			"Python"
		end

	hash_code: INTEGER_32
			-- Hash code of the routine and its closed operands.
		external
			"Python"
		end

feature -- Measurement

	open_count: INTEGER_32
			-- Number of open operands.
		external
			"Python"
		end

feature -- Status report

	callable: BOOLEAN = True
			-- May the routine be called? (Yes.)

	is_target_closed: BOOLEAN
			-- Was the target given when the agent was made?
		external
			"Python"
		end

	valid_operands (args: detachable separate TUPLE): BOOLEAN
			-- Are `args' suitable open operands: at least `open_count' items, each
			-- conforming to the type of its open operand (and Void only if there is none)?
		external
			"Python"
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current agent and `other' stand for the same routine with equal
			-- closed operands and equal `operands'?
		external
			"Python"
		end

feature -- Element change

	set_operands (args: detachable OPEN_ARGS)
			-- Make `args' the operands of the next `apply'.
		require
			valid_operands: valid_operands (args)
		external
			"Python"
		end

feature -- Basic operations

	call (args: detachable separate OPEN_ARGS)
			-- Call the routine with `args' as open operands.
		require
			valid_operands: valid_operands (args)
		deferred
		end

	apply
			-- Call the routine with `operands'.
		require
			valid_operands: valid_operands (operands)
		deferred
		end

	flexible_call (a: detachable separate TUPLE)
			-- Call the routine with the items of `a' as open operands; `a' need not be
			-- of type OPEN_ARGS, only suitable for `valid_operands'.
		require
			valid_operands: valid_operands (a)
		external
			"Python"
		end

feature -- Duplication

	copy (other: like Current)
			-- Stand for the same routine and operands as `other'.
		external
			"Python"
		end

end
