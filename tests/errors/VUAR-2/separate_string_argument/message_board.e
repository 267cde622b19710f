note
	description: "A board keeping the last message posted."

class
	MESSAGE_BOARD

create
	make

feature {NONE} -- Initialization

	make
			-- Empty board.
		do
			create last_message.make_empty
		end

feature -- Access

	last_message: STRING
			-- The message posted last.

feature -- Element change

	post (a_text: separate STRING)
			-- Keep a copy of `a_text'.
		do
			create last_message.make_from_separate (a_text)
		end

end
