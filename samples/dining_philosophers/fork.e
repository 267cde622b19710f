note
	description: "A fork on the table, held by at most one philosopher at a time."

class
	FORK

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Fork number `an_id', lying on the table.
		do
			id := an_id
		ensure
			id_set: id = an_id
			on_table: not is_in_use
		end

feature -- Access

	id: INTEGER
			-- Fork number.

	holder: INTEGER
			-- Seat of the philosopher holding the fork, 0 if it lies on the table.

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
			on_table: not is_in_use
			valid_seat: a_philosopher > 0
		do
			holder := a_philosopher
			use_count := use_count + 1
		ensure
			held: holder = a_philosopher
			counted: use_count = old use_count + 1
		end

	put_down (a_philosopher: INTEGER)
			-- Let philosopher `a_philosopher', who holds the fork, put it back on the table.
		require
			held_by_caller: holder = a_philosopher
		do
			holder := 0
		ensure
			on_table: not is_in_use
		end

invariant
	valid_holder: holder >= 0

end
