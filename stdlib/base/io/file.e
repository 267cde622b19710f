note
	description: "[
		Files designated by a name: creation, opening in a mode, positioning and
		the status of the file in the file system. Reading and writing are those of IO_MEDIUM.
	]"
	implementation: "Externals are provided by the runtime, bound by class and feature name."

deferred class
	FILE

inherit
	IO_MEDIUM

feature {NONE} -- Initialization

	make_with_name (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn', without opening it.
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn', without opening it.
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_open_read (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for reading.
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_open_write (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for writing (emptied or created).
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_open_append (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for writing at its end (created if needed).
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_open_read_write (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for reading and writing.
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_create_read_write (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for reading and writing (emptied or created).
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

	make_open_read_append (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' and open it for reading, and writing at its end.
		require
			fn_not_empty: not fn.is_empty
		external
			"Python"
		end

feature -- Access

	name: STRING_8
			-- Name of the file.
		external
			"Python"
		end

	position: INTEGER_32
			-- Current position (number of characters from the start).
		external
			"Python"
		end

feature -- Measurement

	count: INTEGER_32
			-- Size of the file, in characters.
		external
			"Python"
		end

feature -- Status report

	is_open_append: BOOLEAN
			-- Is the file open for writing at its end?
		external
			"Python"
		end

	end_of_file: BOOLEAN
			-- Has a read reached the end of the file?
		external
			"Python"
		end

	after: BOOLEAN
			-- Is the position past the end of the file?
		external
			"Python"
		end

	off: BOOLEAN
			-- Is the position outside the file?
		external
			"Python"
		end

	is_empty: BOOLEAN
			-- Is the file empty?
		external
			"Python"
		end

	is_directory: BOOLEAN
			-- Is the file a directory?
		external
			"Python"
		end

feature -- Status setting

	open_read
			-- Open the file for reading.
		require
			is_closed: is_closed
		external
			"Python"
		end

	open_write
			-- Open the file for writing (emptied or created).
		require
			is_closed: is_closed
		external
			"Python"
		end

	open_append
			-- Open the file for writing at its end (created if needed).
		require
			is_closed: is_closed
		external
			"Python"
		end

	open_read_write
			-- Open the file for reading and writing.
		require
			is_closed: is_closed
		external
			"Python"
		end

	create_read_write
			-- Open the file for reading and writing (emptied or created).
		require
			is_closed: is_closed
		external
			"Python"
		end

	open_read_append
			-- Open the file for reading, and writing at its end.
		require
			is_closed: is_closed
		external
			"Python"
		end

feature -- Cursor movement

	start
			-- Go to the start of the file.
		require
			file_opened: not is_closed
		external
			"Python"
		end

	finish
			-- Go to the end of the file.
		require
			file_opened: not is_closed
		external
			"Python"
		end

	go (abs_position: INTEGER_32)
			-- Go to position `abs_position'.
		require
			file_opened: not is_closed
			non_negative_argument: abs_position >= 0
		external
			"Python"
		end

	move (offset: INTEGER_32)
			-- Go `offset' characters forward (backward if negative).
		require
			file_opened: not is_closed
		external
			"Python"
		end

	next_line
			-- Skip the rest of the current line.
		require
			is_readable: readable
		external
			"Python"
		end

feature -- Element change

	reset (fn: READABLE_STRING_GENERAL)
			-- Designate the file named `fn' instead (the file must be closed).
		require
			fn_not_empty: not fn.is_empty
			is_closed: is_closed
		external
			"Python"
		end

	rename_file (new_name: READABLE_STRING_GENERAL)
			-- Rename the file in the file system.
		require
			file_exists: exists
			new_name_not_empty: not new_name.is_empty
		external
			"Python"
		end

	delete
			-- Remove the file from the file system.
		require
			exists: exists
		external
			"Python"
		end

	wipe_out
			-- Empty the file.
		require
			is_closed: is_closed
		external
			"Python"
		end

end
