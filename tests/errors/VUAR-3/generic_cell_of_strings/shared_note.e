note
	description: "Keeps a note in a cell on another processor."

class
	SHARED_NOTE

create
	make

feature {NONE} -- Initialization

	make
			-- Create two cells and update them.
		local
			l_note: separate CELL [STRING]
			l_shared: separate CELL [separate STRING]
		do
			create l_note.put ("start") -- E: VUAR(3)
			create l_shared.put ("start")
			update (l_note, l_shared)
		end

feature -- Basic operations

	update (a_note: separate CELL [STRING]; a_shared: separate CELL [separate STRING])
			-- Put a new text into `a_note' and `a_shared'.
		local
			l_text: STRING
		do
			l_text := "moved"
			a_note.put (l_text) -- E: VUAR(3)
			a_shared.put (l_text)
			a_note.put (a_note.item) -- E: VUAR(2)
			print (a_note.item.count)
		end

end
