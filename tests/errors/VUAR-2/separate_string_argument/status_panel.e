note
	description: "Shows the messages posted on a message board."

class
	STATUS_PANEL

create
	make

feature {NONE} -- Initialization

	make
			-- Post a message and show it.
		local
			l_board: separate MESSAGE_BOARD
		do
			create l_board.make
			show_latest (l_board)
		end

feature -- Basic operations

	show_latest (a_board: separate MESSAGE_BOARD)
			-- Post a message on `a_board' and show it.
		do
			a_board.post ("obstacle ahead")
			show (a_board.last_message)
		end

	show (a_text: separate STRING)
			-- Print `a_text'.
		do
			shout (a_text) -- E: VUAR(2)
			print (a_text.count)
			io.put_string (a_text) -- E: VUAR(2)
			io.put_new_line
			shout (create {STRING}.make_from_separate (a_text))
		end

	shout (a_text: STRING)
			-- Print `a_text' followed by an exclamation mark.
		do
			io.put_string (a_text + "!%N")
		end

end
