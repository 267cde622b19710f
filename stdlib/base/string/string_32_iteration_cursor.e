note
	description: "Cursors over the characters of a READABLE_STRING_32, used by `across'."

class
	STRING_32_ITERATION_CURSOR

inherit
	ITERATION_CURSOR [CHARACTER_32]

create
	make

feature {NONE} -- Initialization

	make (s: READABLE_STRING_32)
			-- Cursor on the first character of `s'.
		do
			target := s
			index := 1
		ensure
			target_set: target = s
		end

feature -- Access

	item: CHARACTER_32
			-- Character at the cursor position.
		do
			Result := target.item (index)
		end

	target: READABLE_STRING_32
			-- String being traversed.

	index: INTEGER_32
			-- Position of the cursor in `target'.

feature -- Status report

	after: BOOLEAN
			-- Is the cursor past the last character?
		do
			Result := index > target.count
		end

feature -- Cursor movement

	forth
			-- Move to the next character.
		do
			index := index + 1
		end

end
