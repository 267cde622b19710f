note
	description: "A log of numbered events."

class
	EVENT_LOG

create
	make

feature {NONE} -- Initialization

	make
			-- Empty log.
		do
			create entries.make (10)
		end

feature -- Access

	entries: ARRAYED_LIST [INTEGER]
			-- Codes of the events logged.

feature -- Element change

	add_entry (a_code: INTEGER)
			-- Log an event with `a_code'.
		do
			entries.extend (a_code)
		end

end
