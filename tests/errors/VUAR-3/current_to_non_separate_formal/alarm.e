note
	description: "An alarm that tells its listeners when it goes off."

class
	ALARM

create
	make

feature {NONE} -- Initialization

	make
			-- Alarm with no listener.
		do
			create listeners.make (2)
		end

feature -- Element change

	subscribe (a_listener: separate LISTENER)
			-- Tell `a_listener' about later alarms.
		do
			listeners.extend (a_listener)
		end

	register (a_listener: LISTENER)
			-- Make `a_listener' the owner of the alarm.
		do
			owner := a_listener
		end

feature -- Basic operations

	raise (a_level: INTEGER)
			-- Go off with `a_level'.
		do
			across listeners as c loop
				tell (c.item, a_level)
			end
		end

feature {NONE} -- Implementation

	tell (a_listener: separate LISTENER; a_level: INTEGER)
			-- Tell `a_listener' about an alarm of `a_level'.
		do
			a_listener.notify (a_level)
		end

	listeners: ARRAYED_LIST [separate LISTENER]
			-- Who to tell.

	owner: detachable LISTENER
			-- The owner, if any.

end
