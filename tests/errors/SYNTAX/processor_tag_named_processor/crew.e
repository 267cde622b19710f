note
	description: "Starts two workers."

class
	CREW

create
	make

feature {NONE} -- Initialization

	make
			-- Create two workers and start them.
		local
			l_worker: separate WORKER
			l_helper: separate WORKER
		do
			create <p> l_worker.make (1) -- E: SYNTAX
			create <NONE> l_helper.make (2)
			start (l_worker)
			start (l_helper)
		end

feature -- Basic operations

	start (a_worker: separate WORKER)
			-- Let `a_worker' do one round.
		do
			a_worker.run
		end

end
