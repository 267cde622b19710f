class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BUFFER)
			-- A producer for `a_buffer'.
		do
			buffer := a_buffer
		end

feature -- Basic operations

	fill_later
			-- Sleep, then put an item into the buffer.
		do
			(create {EXECUTION_ENVIRONMENT}).sleep (100_000_000)
			put_into (buffer)
		end

	put_into (a_buffer: separate BUFFER)
			-- Put one item.
		do
			a_buffer.put
		end

feature {NONE} -- Access

	buffer: separate BUFFER
			-- Where items go.

end
