note
	description: "The standard input, output and error streams, seen as text files."
	implementation: "[
		Output on the standard streams goes through the runtime, so one `put_...' call
		writes its text whole even when several processors print at once.
	]"

class
	CONSOLE

inherit
	PLAIN_TEXT_FILE

create {STD_FILES}
	make_open_stdin,
	make_open_stdout,
	make_open_stderr

feature {NONE} -- Initialization

	make_open_stdin (fn: STRING_8)
			-- Attach to the standard input, named `fn'.
		external
			"Python"
		end

	make_open_stdout (fn: STRING_8)
			-- Attach to the standard output, named `fn'.
		external
			"Python"
		end

	make_open_stderr (fn: STRING_8)
			-- Attach to the standard error, named `fn'.
		external
			"Python"
		end

end
