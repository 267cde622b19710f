note
	description: "Where the threadring benchmark's winning node leaves its number."

class
	WINNER

create
	make

feature {NONE} -- Initialization

	make
			-- No winner yet.
		do
			id := 0
		ensure
			not_set: not is_set
		end

feature -- Access

	id: INTEGER
			-- Number of the winning node, 0 until known.

feature -- Status report

	is_set: BOOLEAN
			-- Is the winner known?
		do
			Result := id /= 0
		end

feature -- Element change

	set (an_id: INTEGER)
			-- Record node `an_id' as the winner.
		require
			valid_id: an_id > 0
		do
			id := an_id
		ensure
			set: id = an_id
		end

end
