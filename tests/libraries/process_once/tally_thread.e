class
	TALLY_THREAD

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_owner: PROCESS_ONCE)
		do
			thread_make
			owner := a_owner
		end

feature -- Access

	owner: PROCESS_ONCE

feature -- Basic operations

	execute
		local
			i: INTEGER
		do
			from i := 1 until i > 1000 loop
				owner.add (1)
				i := i + 1
			end
		end

end
