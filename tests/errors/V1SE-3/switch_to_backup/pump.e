note
	description: "A water pump."

class
	PUMP

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER)
			-- Pump number `an_id', stopped.
		do
			id := an_id
		end

feature -- Access

	id: INTEGER
			-- Pump number.

feature -- Status report

	is_faulty: BOOLEAN
			-- Has the pump reported a fault?

	is_running: BOOLEAN
			-- Is the pump running?

feature -- Basic operations

	start
			-- Start pumping.
		do
			is_running := True
		end

end
