note
	description: "Reads the message left in an inbox on another processor."

class
	INBOX_READER

create
	make

feature {NONE} -- Initialization

	make
			-- Create an inbox with a message and read it.
		local
			l_inbox: separate CELL [separate STRING]
		do
			create l_inbox.put ("hello")
			read (l_inbox)
		end

feature -- Basic operations

	read (a_inbox: separate CELL [separate STRING])
			-- Print the length of the message in `a_inbox'.
		local
			l_text: STRING
		do
			print (a_inbox.item.count) -- E: VUTA(3)
			create l_text.make_from_separate (a_inbox.item)
			print (l_text.count)
			separate a_inbox.item as t do
				print (t.count)
			end
		end

end
