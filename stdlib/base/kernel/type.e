note
	description: "[
		Run-time representation of the Eiffel type G. Instances come from
		`generating_type' or from manifest types such as {INTEGER_32}; clients cannot create them.
	]"
	implementation: "Queries on the type itself are `external %"built_in%"' (filled by the code generator)."

class
	TYPE [G]

inherit
	HASHABLE
		rename
			default as any_default
		redefine
			is_equal, out
		end

	PART_COMPARABLE
		rename
			default as any_default,
			is_less as is_strictly_conforming_to alias "<",
			is_less_equal as is_conforming_to alias "<="
		redefine
			is_conforming_to, is_equal, out
		end

	DEBUG_OUTPUT
		rename
			default as any_default
		redefine
			is_equal, out
		end

create {NONE}

convert
	to_string_8: {STRING_8, READABLE_STRING_8, STRING_GENERAL, READABLE_STRING_GENERAL},
	to_string_32: {STRING_32, READABLE_STRING_32}

feature -- Access

	name: IMMUTABLE_STRING_8
			-- Name of the type, as Eiffel writes it (e.g. "ARRAY [INTEGER_32]").
		external
			"built_in"
		end

	name_32: IMMUTABLE_STRING_32
			-- Name of the type, as a Unicode string.
		external
			"built_in"
		end

	type_id: INTEGER_32
			-- Number identifying the type in the running program.
		external
			"built_in"
		end

	generic_parameter_type (i: INTEGER_32): TYPE [detachable ANY]
			-- Type of the `i'-th actual generic parameter.
		require
			i_large_enough: i >= 1
			i_small_enough: i <= generic_parameter_count
		external
			"built_in"
		end

	hash_code: INTEGER_32
			-- Hash code value.
		do
			Result := type_id
		end

feature -- Measurement

	generic_parameter_count: INTEGER_32
			-- Number of actual generic parameters.
		external
			"built_in"
		end

feature -- Status report

	has_default: BOOLEAN
			-- Does the type have a default value (an expanded or detachable type)?
		external
			"built_in"
		end

	is_deferred: BOOLEAN
			-- Is the type's base class deferred?
		external
			"built_in"
		end

	is_expanded: BOOLEAN
			-- Is the type expanded?
		external
			"built_in"
		end

	is_attached: BOOLEAN
			-- Is the type attached?
		external
			"built_in"
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current object and `other' represent the same type?
		external
			"built_in"
		end

	is_strictly_conforming_to alias "<" (other: like Current): BOOLEAN
			-- Does the type conform to `other' and differ from it?
		external
			"built_in"
		end

	is_conforming_to alias "<=" (other: like Current): BOOLEAN
			-- Does the type conform to `other'?
		external
			"built_in"
		end

feature -- Conversion

	adapt alias "[]" (g: detachable G): detachable G
			-- `g' itself, seen with the type G.
		do
			Result := g
		end

	attempted alias "/" (obj: detachable separate ANY): detachable G
			-- `obj' if it is attached to an object of type G, Void otherwise.
		do
			if attached {G} obj as l_g then
				Result := l_g
			end
		end

	default_detachable_value: detachable G
			-- Void, or the default value if G is expanded.
		do
		end

	default: G
			-- Default value of the type.
		require
			has_default: has_default
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- The type's name.
		do
			create Result.make_from_string (name)
		end

	debug_output: READABLE_STRING_32
			-- The type's name.
		do
			Result := name_32
		end

feature -- Features of strings, for code that still treats a type as its name

	plus alias "+" (other: READABLE_STRING_8): STRING_8
			-- The type's name followed by `other'.
		do
			Result := out
			Result.append (other)
		end

	same_string (other: READABLE_STRING_8): BOOLEAN
			-- Is `other' the type's name?
		do
			Result := name.same_string (other)
		end

	is_case_insensitive_equal (other: READABLE_STRING_8): BOOLEAN
			-- Is `other' the type's name, ignoring case?
		do
			Result := name.is_case_insensitive_equal (other)
		end

	as_lower: STRING_8
			-- The type's name in lower case.
		do
			Result := out.as_lower
		end

	as_upper: STRING_8
			-- The type's name in upper case.
		do
			Result := out.as_upper
		end

	to_string_8: STRING_8
			-- The type's name, as a new STRING_8.
		do
			Result := out
		end

	to_string_32: STRING_32
			-- The type's name, as a new STRING_32.
		do
			create Result.make_from_string (name_32)
		end

end
