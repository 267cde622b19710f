note
	description: "A fork on the table, held by at most one philosopher."

class
	FORK

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Fork number `an_id', on the table.
		do
			id := an_id
		ensure
			on_table: not is_in_use
		end

feature -- Access

	id: INTEGER
			-- Fork number.

	holder: INTEGER
			-- Seat of the philosopher holding the fork, 0 if none.

	use_count: INTEGER
			-- Number of times the fork was picked up.

feature -- Status report

	is_in_use: BOOLEAN
			-- Is a philosopher holding the fork?
		do
			Result := holder /= 0
		end

feature -- Basic operations

	pick_up (a_philosopher: INTEGER)
			-- Let philosopher `a_philosopher' take the fork.
		require
			free: not is_in_use
			valid_seat: a_philosopher > 0
		do
			holder := a_philosopher
			use_count := use_count + 1
		ensure
			held: holder = a_philosopher
		end

	put_down
			-- Put the fork back on the table.
		do
			holder := 0
		ensure
			free: not is_in_use
		end

invariant
	valid_holder: holder >= 0

end
