note
	description: "Access to the command-line arguments (as Unicode strings); inherit it or create it."
	implementation: "The arguments come from the host (`i_th_argument' is `external %"Python%"'); the rest is plain Eiffel."

class
	ARGUMENTS_32

inherit
	ITERABLE [IMMUTABLE_STRING_32]

feature -- Access

	argument (i: INTEGER_32): IMMUTABLE_STRING_32
			-- The `i'-th argument of the command that started the program (its name for 0).
		require
			index_large_enough: i >= 0
			index_small_enough: i <= argument_count
		do
			Result := i_th_argument (i)
		end

	argument_array: ARRAY [IMMUTABLE_STRING_32]
			-- The command name (at index 0) and the arguments.
		local
			i: INTEGER_32
		once
			create Result.make_filled (i_th_argument (0), 0, argument_count)
			from
				i := 1
			until
				i > argument_count
			loop
				Result.put (i_th_argument (i), i)
				i := i + 1
			end
			Result.compare_objects
		end

	command_line: IMMUTABLE_STRING_32
			-- The command name and the arguments, separated by blanks.
		local
			i: INTEGER_32
			l_line: STRING_32
		once
			create l_line.make_from_string_general (command_name)
			from
				i := 1
			until
				i > argument_count
			loop
				l_line.append_character (' ')
				l_line.append_string_general (argument (i))
				i := i + 1
			end
			create Result.make_from_string (l_line)
		end

	command_name: IMMUTABLE_STRING_32
			-- Name of the command that started the program.
		do
			Result := argument (0)
		end

	new_cursor: ITERATION_CURSOR [IMMUTABLE_STRING_32]
			-- Cursor over `argument_array' (command name first), for `across'.
		do
			Result := argument_array.new_cursor
		end

feature -- Measurement

	argument_count: INTEGER_32
			-- Number of arguments (the command name not counted).
		external
			"Python"
		ensure
			non_negative: Result >= 0
		end

feature -- Status report

	index_of_word_option (opt: READABLE_STRING_GENERAL): INTEGER_32
			-- Position of the argument that is `option_sign' followed by `opt'; 0 if none.
		require
			opt_meaningful: not opt.is_empty
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i > argument_count or else option_word_equal (argument (i), opt)
			loop
				i := i + 1
			end
			if i <= argument_count then
				Result := i
			end
		end

	index_of_beginning_with_word_option (opt: READABLE_STRING_GENERAL): INTEGER_32
			-- Position of the first argument that starts with `option_sign' and `opt'; 0 if none.
		require
			opt_meaningful: not opt.is_empty
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i > argument_count or else option_word_begins_with (argument (i), opt)
			loop
				i := i + 1
			end
			if i <= argument_count then
				Result := i
			end
		end

	index_of_character_option (o: CHARACTER_32): INTEGER_32
			-- Position of the first option argument containing the letter `o'; 0 if none.
		local
			i: INTEGER_32
		do
			from
				i := 1
			until
				i > argument_count or else option_character_equal (argument (i), o)
			loop
				i := i + 1
			end
			if i <= argument_count then
				Result := i
			end
		end

	separate_character_option_value (o: CHARACTER_32): detachable IMMUTABLE_STRING_32
			-- Argument after the option containing `o', if any (empty if that option is last
			-- or followed by another option; Void if there is no such option).
		local
			p: INTEGER_32
		do
			p := index_of_character_option (o)
			if p /= 0 then
				Result := option_value_after (p)
			end
		end

	separate_word_option_value (opt: READABLE_STRING_GENERAL): detachable IMMUTABLE_STRING_32
			-- Argument after the word option `opt', if any (empty if that option is last
			-- or followed by another option; Void if there is no such option).
		require
			opt_meaningful: not opt.is_empty
		local
			p: INTEGER_32
		do
			p := index_of_word_option (opt)
			if p /= 0 then
				Result := option_value_after (p)
			end
		end

	option_sign: CELL [CHARACTER_32]
			-- Character that starts options (default '-').
		once
			create Result.put ('-')
		end

feature -- Status setting

	set_option_sign (c: CHARACTER_32)
			-- Make `c' the character that starts options.
		do
			option_sign.put (c)
		end

feature {NONE} -- Implementation

	i_th_argument (i: INTEGER_32): IMMUTABLE_STRING_32
			-- The `i'-th argument, from the host.
		external
			"Python"
		end

	option_value_after (p: INTEGER_32): IMMUTABLE_STRING_32
			-- Argument at position `p' + 1, or empty if none or if it is an option.
		do
			if p = argument_count or else argument (p + 1).starts_with_general (option_sign.item.out) then
				create Result.make_empty
			else
				Result := argument (p + 1)
			end
		end

	option_word_equal (arg, w: READABLE_STRING_GENERAL): BOOLEAN
			-- Is `arg' the word option `w'?
		do
			if arg.count = w.count + 1 and then arg.code (1) = option_sign.item.natural_32_code then
				Result := arg.substring (2, arg.count).same_string (w)
			end
		end

	option_word_begins_with (arg, w: READABLE_STRING_GENERAL): BOOLEAN
			-- Does `arg' start with the word option `w'?
		do
			if arg.count > w.count and then arg.code (1) = option_sign.item.natural_32_code then
				Result := arg.substring (2, w.count + 1).same_string (w)
			end
		end

	option_character_equal (arg: READABLE_STRING_GENERAL; c: CHARACTER_32): BOOLEAN
			-- Is `arg' an option containing `c'?
		do
			if arg.count > 1 and then arg.code (1) = option_sign.item.natural_32_code then
				Result := arg.substring (2, arg.count).has (c)
			end
		end

end
