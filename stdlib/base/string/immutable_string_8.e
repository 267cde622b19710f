note
	description: "Immutable strings of 8-bit characters (CHARACTER_8)."
	implementation: "[
		Operations that build a string (`plus', `substring', `as_lower', ...) give a new
		immutable string. Externals are provided by the runtime, bound by class and feature name.
	]"

frozen class
	IMMUTABLE_STRING_8

inherit
	READABLE_STRING_8
		undefine
			is_immutable
		end

	IMMUTABLE_STRING_GENERAL
		rename
			same_string as same_string_general,
			starts_with as starts_with_general,
			ends_with as ends_with_general,
			is_case_insensitive_equal as is_case_insensitive_equal_general,
			item as character_32_item,
			has as character_32_has,
			index_of as character_32_index_of,
			last_index_of as character_32_last_index_of,
			occurrences as character_32_occurrences
		end

create
	make,
	make_empty,
	make_filled,
	make_from_string,
	make_from_separate

convert
	make_from_string ({READABLE_STRING_8, STRING_8}),
	as_string_8: {STRING_8},
	as_string_32: {READABLE_STRING_32, STRING_32}

feature -- Access

	item alias "[]" (i: INTEGER_32): CHARACTER_8
			-- Character at position `i'.
		external
			"Python"
		end

end
