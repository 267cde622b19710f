note
	description: "Truth values True and False, with the boolean operators as features."
	implementation: "[
		Every operation is `external "built_in"': the code generator maps it onto
		Python's operators (`and then' and `or else' short-circuit; `and', `or',
		`xor' and `implies' evaluate both operands, as in Eiffel).
	]"

frozen expanded class
	BOOLEAN

inherit
	HASHABLE
		redefine
			is_hashable, is_equal, out
		end

feature -- Access

	item: BOOLEAN
			-- The value itself.
		external
			"built_in"
		end

	hash_code: INTEGER_32
			-- 1 for True, 0 for False.
		external
			"built_in"
		end

feature -- Status report

	is_hashable: BOOLEAN
			-- May the current value be hashed? (Always.)
		do
			Result := True
		end

feature -- Comparison

	is_equal (other: BOOLEAN): BOOLEAN
			-- Do the current value and `other' have the same truth value?
		external
			"built_in"
		end

feature -- Basic operations

	conjuncted alias "and" (other: BOOLEAN): BOOLEAN
			-- Boolean conjunction (both operands evaluated).
		external
			"built_in"
		end

	conjuncted_semistrict alias "and then" (other: BOOLEAN): BOOLEAN
			-- Boolean conjunction; `other' is evaluated only if the current value is True.
		external
			"built_in"
		end

	disjuncted alias "or" (other: BOOLEAN): BOOLEAN
			-- Boolean disjunction (both operands evaluated).
		external
			"built_in"
		end

	disjuncted_semistrict alias "or else" (other: BOOLEAN): BOOLEAN
			-- Boolean disjunction; `other' is evaluated only if the current value is False.
		external
			"built_in"
		end

	disjuncted_exclusive alias "xor" (other: BOOLEAN): BOOLEAN
			-- Exclusive or.
		external
			"built_in"
		end

	implication alias "implies" (other: BOOLEAN): BOOLEAN
			-- Implication; `other' is evaluated only if the current value is True.
		external
			"built_in"
		end

	negated alias "not": BOOLEAN
			-- Negation.
		external
			"built_in"
		end

feature -- Conversion

	to_integer: INTEGER_32
			-- 1 for True, 0 for False.
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- "True" or "False".
		external
			"built_in"
		end

end
