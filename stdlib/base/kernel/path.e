note
	description: "[
		Names of files and directories as the host's file system reads them: an optional
		root ("/" on Unix; "C:", "C:\", "\" or "\\server\share" on Windows) followed by
		names separated by the directory separator. A path is normalized when it is made
		(doubled and trailing separators dropped, '/' read as '\' on Windows) and never
		changes afterwards: `extended', `parent', ... give new paths.
	]"
	implementation: "[
		Plain Eiffel over a STRING_32 of Unicode characters; the host is consulted only for
		the platform (PLATFORM.is_windows), the case rule for names
		(OPERATING_ENVIRONMENT.case_sensitive_path_names) and, for `absolute_path',
		the working directory.
	]"

class
	PATH

inherit
	HASHABLE
		redefine
			is_equal,
			out
		end

	COMPARABLE
		redefine
			is_equal,
			out
		end

create
	make_empty,
	make_current,
	make_from_string,
	make_from_separate

create {PATH}
	make_from_storage,
	make_from_normalized_storage

feature {NONE} -- Initialization

	make_empty
			-- The empty path (no root, no name).
		do
			create storage.make_empty
		ensure
			is_empty: is_empty
		end

	make_current
			-- The path "." (the working directory).
		do
			create storage.make (1)
			storage.append_character ('.')
		ensure
			not_empty: not is_empty
			is_current: is_current_symbol
		end

	make_from_string (a_path: READABLE_STRING_GENERAL)
			-- The path written `a_path' (normalized).
		do
			create storage.make_from_string_general (a_path)
			normalize
		ensure
			not_empty: not a_path.is_empty implies not is_empty
		end

	make_from_separate (a_path: separate PATH)
			-- A path equal to `a_path', which another processor handles.
		do
			create storage.make_from_separate (a_path.storage)
		ensure
			not_empty: not a_path.is_empty implies not is_empty
		end

	make_from_storage (a_storage: STRING_32)
			-- The path held by `a_storage' (normalized; `a_storage' becomes the path's own).
		do
			storage := a_storage
			normalize
		end

	make_from_normalized_storage (a_storage: STRING_32)
			-- The path held by `a_storage', already normalized (it becomes the path's own).
		do
			storage := a_storage
		ensure
			shared: storage = a_storage
		end

feature -- Access

	name: IMMUTABLE_STRING_32
			-- The path as a string.
		do
			create Result.make_from_string (storage)
		end

	root: detachable PATH
			-- The root of the path, if it has one.
		local
			l_end: INTEGER_32
		do
			l_end := root_end_position
			if l_end = storage.count and l_end > 0 then
				Result := Current
			elseif l_end > 0 then
				create Result.make_from_normalized_storage (storage.substring (1, l_end))
			end
		ensure
			has_root_implies_attached: has_root implies Result /= Void
		end

	parent: PATH
			-- The directory holding `entry': the root and every name but the last
			-- (the working directory "." for a simple relative path).
		local
			l_pos, l_root_end: INTEGER_32
		do
			l_pos := last_separator_position
			if l_pos = 0 then
				if attached root as l_root then
					Result := l_root
				else
					create Result.make_current
				end
			elseif l_pos = 1 then
				create Result.make_from_normalized_storage (storage.substring (1, 1))
			else
				l_root_end := root_end_position
				if l_pos <= l_root_end then
					if l_root_end = storage.count then
						Result := Current
					else
						create Result.make_from_normalized_storage (storage.substring (1, l_root_end))
					end
				else
					create Result.make_from_normalized_storage (storage.substring (1, l_pos - 1))
				end
			end
		end

	entry: detachable PATH
			-- The last name of the path, if there is one other than "." and "..".
		local
			l_pos, l_root_end: INTEGER_32
		do
			l_pos := last_separator_position
			l_root_end := root_end_position
			if l_pos = 0 and l_root_end = 0 then
				Result := Current
			elseif l_pos <= l_root_end then
				if l_root_end < storage.count then
					create Result.make_from_normalized_storage (storage.substring (l_root_end + 1, storage.count))
				end
			else
				create Result.make_from_normalized_storage (storage.substring (l_pos + 1, storage.count))
			end
			if attached Result as r and then (r.is_empty or r.is_current_symbol or r.is_parent_symbol) then
				Result := Void
			end
		ensure
			not_empty: attached Result as r implies not r.is_empty
		end

	extension: detachable IMMUTABLE_STRING_32
			-- What follows the last dot of `entry', if that is not empty.
		local
			l_name: STRING_32
			l_pos, n: INTEGER_32
		do
			if attached entry as l_entry then
				l_name := l_entry.storage
				n := l_name.count
				l_pos := l_name.last_index_of ('.', n)
				if l_pos /= 0 and l_pos /= n then
					create Result.make_from_string (l_name.substring (l_pos + 1, n))
				end
			end
		ensure
			not_empty: attached Result as r implies not r.is_empty
			no_dot: attached Result as r implies not r.has ('.')
		end

	components: ARRAYED_LIST [PATH]
			-- The root, if any, then each name of the path, in order.
		local
			i, l_start, n: INTEGER_32
		do
			create Result.make (5)
			n := storage.count
			l_start := root_end_position
			if l_start > 0 then
				Result.extend (create {PATH}.make_from_normalized_storage (storage.substring (1, l_start)))
			end
			from
				i := l_start + 1
				l_start := i
			until
				i > n + 1
			loop
				if i = n + 1 or else storage.item (i) = directory_separator then
					if i > l_start then
						Result.extend (create {PATH}.make_from_normalized_storage (storage.substring (l_start, i - 1)))
					end
					l_start := i + 1
				end
				i := i + 1
			end
		end

	absolute_path: PATH
			-- The path resolved against the working directory (Current if already absolute).
		do
			Result := absolute_path_in (execution_environment.current_working_path)
		end

	absolute_path_in (a_current_directory: PATH): PATH
			-- The path resolved against `a_current_directory' (Current if already absolute).
		require
			a_current_directory_absolute: a_current_directory.is_absolute
		local
			l_storage: STRING_32
		do
			if storage.is_empty then
				Result := a_current_directory
			elseif is_absolute then
				Result := Current
			else
				if attached root as l_root then
						-- Windows only: "C:name" or "\name".
					if storage.item (1) = directory_separator then
						if attached a_current_directory.root as l_cwd_root then
							create l_storage.make_from_string (l_cwd_root.storage)
						else
							create l_storage.make_from_string (a_current_directory.storage)
						end
						l_storage.append (storage.substring (2, storage.count))
					elseif a_current_directory.storage.count >= 2 and then
						a_current_directory.storage.substring (1, 2).is_case_insensitive_equal (l_root.storage)
					then
						create l_storage.make_from_string (a_current_directory.storage)
						append_with_separator (l_storage, storage.substring (l_root.storage.count + 1, storage.count))
					else
						create l_storage.make_from_string (l_root.storage)
						l_storage.append_character (directory_separator)
						l_storage.append (storage.substring (l_root.storage.count + 1, storage.count))
					end
				else
					create l_storage.make_from_string (a_current_directory.storage)
					append_with_separator (l_storage, storage)
				end
				create Result.make_from_storage (l_storage)
			end
		ensure
			has_root: Result.has_root
		end

	canonical_path: PATH
			-- `absolute_path' with the names "." dropped and each ".." taken away with the name before it.
		local
			l_names: ARRAYED_LIST [PATH]
			l_storage: STRING_32
		do
			l_names := absolute_path.components
			create l_storage.make (storage.count)
			if not l_names.is_empty then
				l_storage.append (l_names.first.storage)
				from
					l_names.start
					l_names.remove
				until
					l_names.after
				loop
					if l_names.item.is_current_symbol then
						l_names.remove
					elseif l_names.item.is_parent_symbol then
						if not l_names.isfirst then
							l_names.back
							l_names.remove
						end
						l_names.remove
					else
						l_names.forth
					end
				end
				across l_names as c loop
					append_with_separator (l_storage, c.item.storage)
				end
			end
			create Result.make_from_normalized_storage (l_storage)
		end

	hash_code: INTEGER_32
			-- Hash code value (ignoring case where path names do).
		do
			if case_sensitive then
				Result := storage.hash_code
			else
				Result := storage.case_insensitive_hash_code
			end
		end

	directory_separator: CHARACTER_8
			-- Separator of names on this platform ('/' or '\').
		do
			if is_windows then
				Result := windows_separator
			else
				Result := unix_separator
			end
		end

	unix_separator: CHARACTER_8 = '/'
			-- Separator of names on Unix.

	windows_separator: CHARACTER_8 = '\'
			-- Separator of names on Windows.

feature -- Status report

	is_empty: BOOLEAN
			-- Is the path empty (no root, no name)?
		do
			Result := storage.is_empty
		end

	has_root: BOOLEAN
			-- Does the path start with a root?
		do
			Result := root_end_position > 0
		ensure
			definition: Result implies not is_empty
		end

	is_absolute: BOOLEAN
			-- Does the path start with a root that ends with a separator
			-- (any root on Unix; "C:\" or "\" but not "C:" on Windows)?
		local
			l_end: INTEGER_32
		do
			l_end := root_end_position
			if l_end > 0 then
				Result := not is_windows or else storage.item (l_end) = directory_separator
			end
		end

	is_relative: BOOLEAN
			-- Is the path not absolute?
		do
			Result := not is_absolute
		end

	is_simple: BOOLEAN
			-- Is the path empty or a single name without root?
		do
			Result := storage.is_empty or else (root_end_position = 0 and last_separator_position = 0)
		end

	is_current_symbol: BOOLEAN
			-- Is the path "."?
		do
			Result := storage.count = 1 and then storage.item (1) = '.'
		end

	is_parent_symbol: BOOLEAN
			-- Is the path ".."?
		do
			Result := storage.count = 2 and then (storage.item (1) = '.' and storage.item (2) = '.')
		end

	has_extension (a_ext: READABLE_STRING_GENERAL): BOOLEAN
			-- Is `a_ext' the extension of `entry', ignoring case?
		require
			a_ext_not_empty: not a_ext.is_empty
			a_ext_has_no_dot: not a_ext.has ('.')
		do
			Result := attached extension as l_ext and then l_ext.is_case_insensitive_equal_general (a_ext)
		end

feature -- Comparison

	same_as (other: detachable PATH): BOOLEAN
			-- Is `other' the same path (compared as the platform compares names, without resolving)?
		do
			if other = Current then
				Result := True
			elseif attached other as o then
				if case_sensitive then
					Result := storage.same_string (o.storage)
				else
					Result := storage.is_case_insensitive_equal (o.storage)
				end
			end
		end

	is_equal (other: like Current): BOOLEAN
			-- Is `other' the same path?
		do
			Result := same_as (other)
		end

	is_less alias "<" (other: like Current): BOOLEAN
			-- Does the path come before `other' (by its characters, ignoring case where names do)?
		do
			if case_sensitive then
				Result := storage < other.storage
			else
				Result := storage.as_lower < other.storage.as_lower
			end
		end

	is_case_sensitive_equal (other: PATH): BOOLEAN
			-- Has `other' the same characters?
		do
			Result := other = Current or else storage.same_string (other.storage)
		end

	is_case_insensitive_equal (other: PATH): BOOLEAN
			-- Has `other' the same characters, ignoring case?
		do
			Result := other = Current or else storage.is_case_insensitive_equal (other.storage)
		end

feature -- Element change

	extended (a_name: READABLE_STRING_GENERAL): PATH
			-- A new path: this one followed by `a_name' (a separator between them unless
			-- the path is empty or only a root).
		require
			a_name_not_empty: not a_name.is_empty
			a_name_has_no_root: not is_empty implies not (create {PATH}.make_from_string (a_name)).has_root
		local
			l_storage: STRING_32
		do
			create l_storage.make_from_string (storage)
			if l_storage.is_empty or else root_end_position = l_storage.count then
				l_storage.append_string_general (a_name)
			else
				append_with_separator (l_storage, a_name)
			end
			create Result.make_from_storage (l_storage)
		ensure
			not_empty: not Result.is_empty
		end

	extended_path alias "+" (a_path: PATH): PATH
			-- A new path: this one followed by `a_path' (a separator between them unless
			-- the path is empty or only a root).
		require
			a_path_not_empty: not a_path.is_empty
			a_path_has_no_root: not is_empty implies not a_path.has_root
		local
			l_storage: STRING_32
		do
			create l_storage.make_from_string (storage)
			if l_storage.is_empty or else root_end_position = l_storage.count then
				l_storage.append (a_path.storage)
			else
				append_with_separator (l_storage, a_path.storage)
			end
			create Result.make_from_normalized_storage (l_storage)
		ensure
			not_empty: not Result.is_empty
		end

	appended (a_extra: READABLE_STRING_GENERAL): PATH
			-- A new path: this one with `a_extra' added to its last name (no separator added).
		require
			a_extra_not_empty: not a_extra.is_empty
		local
			l_storage: STRING_32
		do
			create l_storage.make_from_string (storage)
			l_storage.append_string_general (a_extra)
			create Result.make_from_storage (l_storage)
		ensure
			not_empty: not Result.is_empty
		end

	appended_with_extension (a_ext: READABLE_STRING_GENERAL): PATH
			-- A new path: this one with a dot (unless `entry' ends with one) and `a_ext' added to its last name.
		require
			a_ext_not_empty: not a_ext.is_empty
			a_ext_has_no_dot: not a_ext.has ('.')
			a_ext_has_no_directory_separator: not a_ext.has (windows_separator) and not a_ext.has (unix_separator)
			has_entry: entry /= Void
		local
			l_storage: STRING_32
		do
			create l_storage.make_from_string (storage)
			if l_storage.item (l_storage.count) /= '.' then
				l_storage.append_character ('.')
			end
			l_storage.append_string_general (a_ext)
			create Result.make_from_normalized_storage (l_storage)
		ensure
			not_empty: not Result.is_empty
		end

feature -- Output

	out: STRING_8
			-- The path in UTF-8 (see `utf_8_name').
		do
			Result := utf_8_name
		end

	utf_8_name: STRING_8
			-- The characters of the path encoded in UTF-8.
		local
			i, n, c: INTEGER_32
		do
			n := storage.count
			create Result.make (n)
			from
				i := 1
			until
				i > n
			loop
				c := storage.item (i).code
				if c < 0x80 then
					Result.append_character (c.to_character_8)
				elseif c < 0x800 then
					Result.append_character ((0xC0 + c // 0x40).to_character_8)
					Result.append_character ((0x80 + c \\ 0x40).to_character_8)
				elseif c < 0x10000 then
					Result.append_character ((0xE0 + c // 0x1000).to_character_8)
					Result.append_character ((0x80 + (c // 0x40) \\ 0x40).to_character_8)
					Result.append_character ((0x80 + c \\ 0x40).to_character_8)
				else
					Result.append_character ((0xF0 + c // 0x40000).to_character_8)
					Result.append_character ((0x80 + (c // 0x1000) \\ 0x40).to_character_8)
					Result.append_character ((0x80 + (c // 0x40) \\ 0x40).to_character_8)
					Result.append_character ((0x80 + c \\ 0x40).to_character_8)
				end
				i := i + 1
			end
		end

feature {PATH} -- Implementation

	storage: STRING_32
			-- The characters of the path, normalized.

feature {NONE} -- Implementation

	normalize
			-- Make `storage' normal: separators written `directory_separator', none doubled
			-- (but the "\\" that starts a Windows UNC name), none at the end unless it ends the root.
		local
			l_result: STRING_32
			i, n: INTEGER_32
			c: CHARACTER_32
			l_in_separator, l_unc: BOOLEAN
		do
			n := storage.count
			if n > 0 then
				create l_result.make (n)
				i := 1
				if is_windows and then n >= 5 and then
					(is_separator (storage.item (1)) and is_separator (storage.item (2)) and not is_separator (storage.item (3)))
				then
					l_result.append_character (windows_separator)
					l_result.append_character (windows_separator)
					l_unc := True
					i := 3
				end
				from
				until
					i > n
				loop
					c := storage.item (i)
					if is_separator (c) then
						if not l_in_separator then
							l_result.append_character (directory_separator)
						end
						l_in_separator := True
					else
						l_result.append_character (c)
						l_in_separator := False
					end
					i := i + 1
				end
				storage := l_result
				if l_unc and then root_end_position = 0 then
					storage.remove_head (1)
				end
				if storage.item (storage.count) = directory_separator and then root_end_position < storage.count then
					storage.remove_tail (1)
				end
			end
		end

	root_end_position: INTEGER_32
			-- Position of the last character of the root, 0 if there is no root.
		local
			n, l_pos: INTEGER_32
			c: CHARACTER_32
		do
			n := storage.count
			if n > 0 then
				if not is_windows then
					if storage.item (1) = unix_separator then
						Result := 1
					end
				elseif n = 1 then
					if storage.item (1) = windows_separator then
						Result := 1
					end
				else
					c := storage.item (1)
					if storage.item (2) = ':' and then ((c >= 'a' and c <= 'z') or (c >= 'A' and c <= 'Z')) then
						if n >= 3 and then storage.item (3) = windows_separator then
							Result := 3
						else
							Result := 2
						end
					elseif c = windows_separator and storage.item (2) /= windows_separator then
						Result := 1
					elseif n >= 5 and then (c = windows_separator and storage.item (3) /= windows_separator) then
							-- "\\server\share", with an optional separator after it.
						l_pos := storage.index_of (windows_separator, 4)
						if l_pos > 0 and l_pos < n then
							l_pos := storage.index_of (windows_separator, l_pos + 1)
							if l_pos > 0 then
								Result := l_pos
							else
								Result := n
							end
						end
					end
				end
			end
		ensure
			non_negative: Result >= 0
			not_too_big: Result <= storage.count
		end

	last_separator_position: INTEGER_32
			-- Position of the last separator of the path, 0 if there is none.
		do
			if not storage.is_empty then
				Result := storage.last_index_of (directory_separator, storage.count)
			end
		ensure
			non_negative: Result >= 0
		end

	append_with_separator (a_storage: STRING_32; a_name: READABLE_STRING_GENERAL)
			-- Append `a_name' to `a_storage', with a separator between them unless
			-- one is already there or `a_storage' is empty.
		do
			if not a_storage.is_empty and then
				(a_storage.item (a_storage.count) /= directory_separator and
				(a_name.is_empty or else not is_separator (a_name.item (1))))
			then
				a_storage.append_character (directory_separator)
			end
			a_storage.append_string_general (a_name)
		end

	is_separator (c: CHARACTER_32): BOOLEAN
			-- Does `c' separate names on this platform?
		do
			Result := c = unix_separator or else (is_windows and c = windows_separator)
		end

	is_windows: BOOLEAN
			-- Is the platform Windows?
		do
			Result := platform.is_windows
		end

	case_sensitive: BOOLEAN
			-- Does case matter in names of files on this platform?
		do
			Result := Operating_environment.case_sensitive_path_names
		end

	platform: PLATFORM
			-- Properties of the platform.
		once
			create Result
		end

	execution_environment: EXECUTION_ENVIRONMENT
			-- The environment the program runs in.
		once
			create Result
		end

end
