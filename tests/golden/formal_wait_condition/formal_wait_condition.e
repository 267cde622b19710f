class
	FORMAL_WAIT_CONDITION

create
	make

feature {NONE} -- Initialization

	make
			-- A consumer whose argument is of a formal generic type with a separate constraint
			-- waits in its precondition until a producer has filled the buffer.
		local
			b: separate BUFFER
			c: CONSUMER [separate BUFFER]
			p: separate PRODUCER
		do
			create b
			create c
			create p.make (b)
			start (p)
			c.take (b)
		end

	start (a_producer: separate PRODUCER)
			-- Let `a_producer' fill its buffer later.
		do
			a_producer.fill_later
		end

end
