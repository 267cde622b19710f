class
	CONSUMER

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_buffer: BUFFER; a_count: INTEGER)
		do
			thread_make
			buffer := a_buffer
			count := a_count
		end

feature -- Access

	buffer: BUFFER
	count: INTEGER
	sum: INTEGER

feature -- Basic operations

	execute
		local
			i: INTEGER
		do
			from i := 1 until i > count loop
				sum := sum + buffer.take
				i := i + 1
			end
		end

end
