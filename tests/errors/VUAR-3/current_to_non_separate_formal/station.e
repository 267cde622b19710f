note
	description: "A control station that listens to an alarm."

class
	STATION

inherit
	LISTENER

create
	make

feature {NONE} -- Initialization

	make
			-- Create an alarm and connect to it.
		local
			l_alarm: separate ALARM
		do
			create l_alarm.make
			connect (l_alarm)
		end

feature -- Basic operations

	connect (a_alarm: separate ALARM)
			-- Listen to `a_alarm'.
		do
			a_alarm.subscribe (Current)
			a_alarm.register (Current) -- E: VUAR(3)
			a_alarm.raise (2)
		end

	notify (a_level: INTEGER)
			-- Report an alarm of `a_level'.
		do
			print ("alarm level " + a_level.out + "%N")
		end

end
