note
	description: "A fork shared by two philosophers."

class
	FORK

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Fork number `an_id', on the table.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Fork number.

	is_in_use: BOOLEAN
			-- Is someone holding the fork?

feature -- Basic operations

	pick_up
			-- Take the fork.
		do
			is_in_use := True
		end

	put_down
			-- Put the fork back.
		do
			is_in_use := False
		end

end
