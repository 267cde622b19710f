note
	description: "Starts workers on their own processors."

class
	WORKSHOP

create
	make

feature {NONE} -- Initialization

	make
			-- Start two workers.
		do
			last_worker := new_worker (1)
			if attached {separate WORKER} last_worker as w then
				w.run -- E: VUTA(3)
			end
			start_worker (new_worker (2))
		end

feature -- Basic operations

	new_worker (an_id: INTEGER): separate WORKER
			-- A new worker numbered `an_id'.
		do
			create Result.make (an_id)
			Result.run -- E: VUTA(3)
		end

	start_worker (a_thing: separate ANY)
			-- Run `a_thing' if it is a worker.
		do
			if attached {separate WORKER} a_thing as w then
				w.run
				print ("worker " + w.id.out + " started%N")
			end
		end

feature -- Access

	last_worker: detachable separate WORKER
			-- The worker started last.

end
