note
	description: "A processor that prints each call it serves, with its count so far."

class
	LOGGER

create
	make

feature {NONE} -- Initialization

	make (a_id: INTEGER)
		do
			id := a_id
		end

feature -- Access

	id: INTEGER

	count: INTEGER

	peer: detachable separate LOGGER

feature -- Basic operations

	put (code: INTEGER)
		do
			count := count + 1
			print ("L" + id.out + " #" + count.out + ": " + code.out + "%N")
		end

	set_peer (a_peer: separate LOGGER)
		do
			peer := a_peer
		end

	relay (other: separate LOGGER; code: INTEGER)
			-- Log `code' here, then on `other'.
		do
			put (code)
			other.put (code)
		end

	fill (n: INTEGER)
			-- Put 100 + 1 .. 100 + `n' on `peer', one reservation each.
		local
			i: INTEGER
		do
			if attached peer as l_peer then
				from
					i := 1
				until
					i > n
				loop
					put_one (l_peer, 100 + i)
					i := i + 1
				end
			end
		end

feature {NONE} -- Implementation

	put_one (other: separate LOGGER; code: INTEGER)
		do
			other.put (code)
		end

end
