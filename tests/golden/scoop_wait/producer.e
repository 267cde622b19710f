class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (b: separate BUFFER; n: INTEGER)
		do
			buffer := b
			count := n
		end

feature -- Basic operations

	run
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > count
			loop
				store (buffer, i * i)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	buffer: separate BUFFER

	count: INTEGER

	store (b: separate BUFFER; v: INTEGER)
			-- Wait until `b' has room, then put `v'.
		require
			room: not b.is_full
		do
			b.put (v)
			print ("put " + v.out + "%N")
		end

end
