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

	make_with_path (a_path: PATH)
			-- Designate the file at `a_path', without opening it.
		require
			a_path_not_empty: not a_path.is_empty
		do
			make_with_name (a_path.name)
		ensure
			path_set: path.same_as (a_path)
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

	path: PATH
			-- The file's name as a path.
		do
			create Result.make_from_string (path_name)
		ensure
			entry_not_empty: not Result.is_empty
		end

	position: INTEGER_32
			-- Current position (number of characters from the start).
		external
			"Python"
		end

	date: INTEGER_32
			-- Time of the last modification, in seconds since 1970-01-01 00:00 UTC.
		require
			file_exists: exists
		external
			"Python"
		end

	access_date: INTEGER_32
			-- Time of the last access, in seconds since 1970-01-01 00:00 UTC.
		require
			file_exists: exists
		external
			"Python"
		end

	change_date: INTEGER_32
			-- Time of the last change of the file's status, in seconds since 1970-01-01 00:00 UTC.
		require
			file_exists: exists
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

	path_exists: BOOLEAN
			-- Is there an entry of that name in the file system (a symbolic link
			-- counts even when what it points to is missing)?
		external
			"Python"
		end

	is_creatable: BOOLEAN
			-- Could the file be created: it does not exist and its directory may be written?
		external
			"Python"
		end

	is_plain: BOOLEAN
			-- Is the file an ordinary file?
		require
			file_exists: exists
		external
			"Python"
		end

	is_directory: BOOLEAN
			-- Is the file a directory?
		require
			file_exists: exists
		external
			"Python"
		end

	is_device: BOOLEAN
			-- Is the file a device (block or character special file)?
		require
			file_exists: exists
		external
			"Python"
		end

	is_block: BOOLEAN
			-- Is the file a block special file?
		require
			file_exists: exists
		external
			"Python"
		end

	is_character: BOOLEAN
			-- Is the file a character special file?
		require
			file_exists: exists
		external
			"Python"
		end

	is_fifo: BOOLEAN
			-- Is the file a named pipe?
		require
			file_exists: exists
		external
			"Python"
		end

	is_socket: BOOLEAN
			-- Is the file a named socket?
		require
			file_exists: exists
		external
			"Python"
		end

	is_symlink: BOOLEAN
			-- Is the file a symbolic link (not followed)?
		require
			file_exists: path_exists
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

	reset_path (fp: PATH)
			-- Designate the file at `fp' instead, closing the file if it is open.
		require
			fp_not_empty: not fp.is_empty
		do
			if not is_closed then
				close
			end
			reset (fp.name)
		ensure
			file_closed: is_closed
		end

	rename_file (new_name: READABLE_STRING_GENERAL)
			-- Rename the file in the file system; the object designates it under `new_name'.
		require
			new_name_not_empty: not new_name.is_empty
			file_exists: exists
		external
			"Python"
		end

	rename_path (new_path: PATH)
			-- Rename the file in the file system to `new_path'.
		require
			new_path_not_empty: not new_path.is_empty
			file_exists: exists
		do
			rename_file (new_path.name)
		end

	touch
			-- Set the times of last access and modification to now.
		require
			file_exists: exists
		external
			"Python"
		end

	delete
			-- Remove the file's name from the file system (a directory must be empty).
		require
			exists: path_exists
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

feature {NONE} -- Implementation

	path_name: STRING_32
			-- The file's name with every character kept (what `path' is made from).
		external
			"Python"
		end

end
