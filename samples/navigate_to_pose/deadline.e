note
	description: "Fires a STOP_SIGNALER some seconds after `arm', unless disarmed before."

class
	DEADLINE

create
	make

feature {NONE} -- Initialization

	make (a_stop: separate STOP_SIGNALER; a_seconds: REAL_64)
			-- Fire `a_stop' `a_seconds' after `arm'.
		do
			stop := a_stop
			seconds := a_seconds
			create timer.make
		end

feature -- Access

	seconds: REAL_64
			-- Seconds from `arm' to the stop.

feature -- Basic operations

	arm
			-- Start counting.
		do
			timer.call_after (seconds, agent fire)
		end

	disarm
			-- Never fire.
		do
			timer.cancel
		end

feature {NONE} -- Implementation

	stop: separate STOP_SIGNALER
			-- What fires.

	timer: TIMER
			-- Calls `fire' on this processor.

	fire
			-- Request the stop.
		do
			request (stop)
		end

	request (a_stop: separate STOP_SIGNALER)
			-- Request `a_stop'.
		do
			a_stop.request_stop
		end

end
