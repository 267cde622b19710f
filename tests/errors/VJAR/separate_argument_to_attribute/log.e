note
	description: "A log counting the events written to it."

class
	LOG

create
	make

feature {NONE} -- Initialization

	make
			-- Empty log.
		do
			count := 0
		end

feature -- Access

	count: INTEGER
			-- Number of events written.

feature -- Element change

	write_event
			-- Record one more event.
		do
			count := count + 1
		end

end
