note
	description: "Tells the parts of a behaviour that they should stop."

class
	STOP_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- No stop requested.
		do
			is_stop_requested := False
		ensure
			running: not is_stop_requested
		end

feature -- Status report

	is_stop_requested: BOOLEAN
			-- Should everyone stop?

feature -- Basic operations

	request_stop
			-- Ask everyone to stop.
		do
			is_stop_requested := True
		ensure
			requested: is_stop_requested
		end

end
