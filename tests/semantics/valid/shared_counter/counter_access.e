note
	description: "Access to the one counter of the program, whichever processor asks."

class
	COUNTER_ACCESS

feature -- Access

	counter: separate COUNTER
			-- The counter shared by every processor.
		once ("PROCESS")
			create Result.make
		end

end
