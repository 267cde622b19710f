class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (b: separate BUFFER; n: INTEGER)
		do
			buffer := b
			count := n
		end

feature -- Access

	total: INTEGER

	taken: INTEGER

	is_done: BOOLEAN
		do
			Result := taken = count
		end

feature -- Basic operations

	run
		do
			from
			until
				taken = count
			loop
				take (buffer)
			end
		end

feature {NONE} -- Implementation

	buffer: separate BUFFER

	count: INTEGER

	take (b: separate BUFFER)
			-- Wait until `b' has an item, then take it.
		require
			something: not b.is_empty
		do
			total := total + b.item
			print ("got " + b.item.out + "%N")
			b.remove
			taken := taken + 1
		end

end
