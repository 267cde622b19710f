note
	description: "[
		An event that agents subscribe to: `publish (v)' calls every subscribed agent with `v',
		in subscription order, on the processor of the event (the subscribers are agents of
		that region; one that must reach another processor makes a separate call). Use
		EVENT [BOOLEAN] or EVENT [INTEGER] for a plain notification, EVENT [POSE_2D] to pass data.
	]"

class
	EVENT [G]

create
	make

feature {NONE} -- Initialization

	make
			-- Event with no subscriber.
		do
			create subscribers.make (2)
		ensure
			none: subscriber_count = 0
		end

feature -- Access

	subscriber_count: INTEGER
			-- Agents subscribed.
		do
			Result := subscribers.count
		end

	publish_count: INTEGER
			-- Times `publish' was called.

feature -- Status report

	has (a_action: PROCEDURE [G]): BOOLEAN
			-- Is `a_action' subscribed?
		do
			Result := subscribers.has (a_action)
		end

feature -- Element change

	subscribe (a_action: PROCEDURE [G])
			-- Call `a_action' on every `publish'.
		do
			subscribers.extend (a_action)
		ensure
			one_more: subscriber_count = old subscriber_count + 1
		end

	unsubscribe (a_action: PROCEDURE [G])
			-- No longer call `a_action'.
		do
			subscribers.prune_all (a_action)
		ensure
			gone: not has (a_action)
		end

	unsubscribe_all
			-- No subscriber any more.
		do
			subscribers.wipe_out
		ensure
			none: subscriber_count = 0
		end

feature -- Basic operations

	publish (a_value: G)
			-- Call every subscriber with `a_value', in subscription order.
		local
			i: INTEGER
			snapshot: ARRAYED_LIST [PROCEDURE [G]]
		do
			publish_count := publish_count + 1
			snapshot := subscribers.twin
			from i := 1 until i > snapshot.count loop
				snapshot [i].call ([a_value])
				i := i + 1
			end
		ensure
			counted: publish_count = old publish_count + 1
		end

feature {NONE} -- Implementation

	subscribers: ARRAYED_LIST [PROCEDURE [G]]
			-- Subscribed agents, in order.

end
