note
	description: "[
		Attributes a thread is launched with (`launch_with_attributes'). Python threads
		have one priority: `min_priority', `default_priority' and `max_priority' are all
		0. A detached thread can still be joined (as in EiffelThread, where it only
		affects the operating system's join).
	]"

class
	THREAD_ATTRIBUTES

create
	make

feature {NONE} -- Initialization

	make
			-- Attributes with the default priority, detached.
		do
			priority := default_priority
			detached := True
		ensure
			default_priority: priority = default_priority
			detached: detached
		end

feature -- Access

	priority: INTEGER_32
			-- Priority of the thread.

	detached: BOOLEAN
			-- Is the thread created detached?

	default_priority: INTEGER_32 = 0
			-- Priority of a thread launched without attributes.

	min_priority: INTEGER_32 = 0
			-- Lowest priority.

	max_priority: INTEGER_32 = 0
			-- Highest priority.

feature -- Element change

	set_priority (a_priority: INTEGER_32)
			-- Launch with priority `a_priority'.
		require
			valid_priority: a_priority >= min_priority and a_priority <= max_priority
		do
			priority := a_priority
		ensure
			priority_set: priority = a_priority
		end

	set_detached (a_detached: BOOLEAN)
			-- Launch detached if `a_detached'.
		do
			detached := a_detached
		ensure
			detached_set: detached = a_detached
		end

invariant
	priority_in_range: priority >= min_priority and priority <= max_priority

end
