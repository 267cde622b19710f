note
	description: "[
		The environment the program runs in: environment variables, the working
		directory, running commands, the number of processors, and waiting (`sleep').
	]"
	implementation: "[
		Host services are `external "Python"'. `sleep' uses the runtime's clock, so a
		processor that sleeps lets the others run, and tests can use virtual time.
	]"

class
	EXECUTION_ENVIRONMENT

feature -- Access

	arguments: ARGUMENTS_32
			-- The command-line arguments.
		once
			create Result
		end

	command_line: ARGUMENTS_32
			-- The command-line arguments.
		do
			Result := arguments
		end

	item (key: READABLE_STRING_GENERAL): detachable STRING_32
			-- Value of the environment variable `key', if it is set.
		require
			key_not_empty: not key.is_empty
		external
			"Python"
		end

	get (key: READABLE_STRING_GENERAL): detachable STRING_8
			-- Value of the environment variable `key', if it is set, as a STRING_8.
		require
			key_not_empty: not key.is_empty
		do
			if attached item (key) as l_value then
				Result := l_value.as_string_8
			end
		end

	current_working_directory: STRING_8
			-- The working directory.
		external
			"Python"
		end

	current_working_path: PATH
			-- The working directory, as a path.
		do
			create Result.make_from_string (current_working_directory)
		end

	home_directory_name: detachable STRING_8
			-- The user's home directory, if known.
		external
			"Python"
		end

	home_directory_path: detachable PATH
			-- The user's home directory, if known, as a path.
		do
			if attached home_directory_name as l_name then
				create Result.make_from_string (l_name)
			end
		end

	root_directory_name: STRING_8
			-- The root directory of the file system.
		external
			"Python"
		end

	default_shell: STRING_32
			-- The command interpreter that `system' and `launch' use.
		external
			"Python"
		end

	available_cpu_count: NATURAL_32
			-- Number of processors (cores) of the machine.
		external
			"Python"
		end

	return_code: INTEGER_32
			-- Exit status of the last command run by `system'.
		external
			"Python"
		end

feature -- Status setting

	put (value, key: READABLE_STRING_GENERAL)
			-- Set the environment variable `key' to `value'.
		require
			key_not_empty: not key.is_empty
		external
			"Python"
		end

	change_working_directory (path: READABLE_STRING_GENERAL)
			-- Make `path' the working directory.
		external
			"Python"
		end

	change_working_path (path: PATH)
			-- Make `path' the working directory.
		do
			change_working_directory (path.name)
		end

feature -- Basic operations

	sleep (nanoseconds: INTEGER_64)
			-- Suspend the current processor for at least `nanoseconds' nanoseconds.
		require
			non_negative_nanoseconds: nanoseconds >= 0
		external
			"Python"
		end

	system (s: READABLE_STRING_GENERAL)
			-- Run the command `s' and wait for it to end; its exit status is `return_code'.
		external
			"Python"
		end

	launch (s: READABLE_STRING_GENERAL)
			-- Start the command `s' without waiting for it.
		external
			"Python"
		end

end
