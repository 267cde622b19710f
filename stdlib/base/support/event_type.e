note
	description: "[
		An event that agents subscribe to: `publish' calls every subscribed agent, in the order
		they subscribed, with the event's data. Subscriptions can be suspended and restored.
	]"

class
	EVENT_TYPE [EVENT_DATA -> detachable TUPLE create default_create end]

inherit
	ANY
		redefine
			default_create
		end

create
	default_create

feature {NONE} -- Initialization

	default_create
			-- An event with no subscriber.
		do
			create subscribers.make (2)
		end

feature -- Access

	subscribers: ARRAYED_LIST [PROCEDURE [EVENT_DATA]]
			-- The agents called by `publish', in subscription order.

	count: INTEGER
			-- Number of subscriptions.
		do
			Result := subscribers.count
		end

feature -- Status report

	has (an_action: PROCEDURE [EVENT_DATA]): BOOLEAN
			-- Is `an_action' subscribed?
		do
			Result := subscribers.has (an_action)
		end

	is_suspended: BOOLEAN
			-- Are publications ignored?

feature -- Element change

	subscribe (an_action: PROCEDURE [EVENT_DATA])
			-- Call `an_action' at each publication.
		require
			not_subscribed: not has (an_action)
		do
			subscribers.extend (an_action)
		ensure
			subscribed: has (an_action)
		end

	unsubscribe (an_action: PROCEDURE [EVENT_DATA])
			-- Stop calling `an_action'.
		do
			subscribers.start
			subscribers.prune (an_action)
		ensure
			unsubscribed: not has (an_action)
		end

	wipe_out
			-- Remove every subscription.
		do
			subscribers.wipe_out
		ensure
			no_subscriber: count = 0
		end

feature -- Basic operations

	publish (args: EVENT_DATA)
			-- Call every subscribed agent with `args', unless suspended.
		do
			if not is_suspended then
				across subscribers.twin as c loop
					c.item.call (args)
				end
			end
		end

	suspend_subscription
			-- Ignore publications until `restore_subscription'.
		do
			is_suspended := True
		ensure
			suspended: is_suspended
		end

	restore_subscription
			-- Publish again.
		do
			is_suspended := False
		ensure
			restored: not is_suspended
		end

end
