note
	description: "Immutable strings of 32-bit characters (CHARACTER_32, Unicode)."
	implementation: "[
		Operations that build a string (`plus', `substring', `as_lower', ...) give a new
		immutable string. Externals are provided by the runtime, bound by class and feature name.
	]"

frozen class
	IMMUTABLE_STRING_32

inherit
	READABLE_STRING_32
		undefine
			is_immutable
		end

	IMMUTABLE_STRING_GENERAL
		rename
			same_string as same_string_general,
			starts_with as starts_with_general,
			ends_with as ends_with_general,
			is_case_insensitive_equal as is_case_insensitive_equal_general
		end

create
	make,
	make_empty,
	make_filled,
	make_from_string,
	make_from_string_general,
	make_from_separate

convert
	make_from_string ({READABLE_STRING_32, STRING_32}),
	make_from_string_general ({READABLE_STRING_8, STRING_8}),
	as_string_8: {READABLE_STRING_8, STRING_8},
	as_string_32: {STRING_32}

feature -- Access

	item alias "[]" (i: INTEGER_32): CHARACTER_32
			-- Character at position `i'.
		external
			"Python"
		end

end
