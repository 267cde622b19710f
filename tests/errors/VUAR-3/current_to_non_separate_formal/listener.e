note
	description: "Something told about alarms."

deferred class
	LISTENER

feature -- Basic operations

	notify (a_level: INTEGER)
			-- React to an alarm of `a_level'.
		deferred
		end

end
