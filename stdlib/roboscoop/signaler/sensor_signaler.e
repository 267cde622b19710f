note
	description: "[
		A signaler fed by sensor messages. It knows when its last message came, on the runtime's
		clock (virtual in simulated runs), and reports stale data: `is_stale' holds when no message
		came for longer than `stale_after' seconds (default 0.5 s), and before the first one.
		Staleness is computed when asked: a controller that checks it at its rate, or a guard
		`not s.is_stale' (woken by the next message), sees it. A wait condition on `is_stale'
		itself needs `watch_staleness': nothing else runs on the signaler's processor when its
		topic is silent, so nothing would wake the waiter.
	]"

deferred class
	SENSOR_SIGNALER

feature {NONE} -- Initialization

	make_sensor
			-- No message yet; stale after `Default_stale_after' seconds.
		do
			create clock.make
			create subscribers.make (1)
			stale_after := Default_stale_after
		ensure
			no_reading: not has_reading
			stale: is_stale
		end

feature -- Access

	update_count: INTEGER
			-- Readings received.

	received_at: REAL_64
			-- Runtime clock (s) when the last reading arrived (0 when none did).

	stale_after: REAL_64
			-- Seconds without a reading after which the data is stale.

	Default_stale_after: REAL_64 = 0.5
			-- Default `stale_after'.

	age: REAL_64
			-- Seconds since the last reading (the time since the start of the clock when none came).
		do
			Result := clock.now - received_at
		end

	subscriber: detachable ROS_SUBSCRIBER [ROS_MESSAGE]
			-- The first subscription feeding Current (Void: unconnected).
		do
			if not subscribers.is_empty then
				Result := subscribers.first
			end
		end

	subscriber_count: INTEGER
			-- Subscriptions feeding Current.
		do
			Result := subscribers.count
		end

feature -- Status report

	has_reading: BOOLEAN
			-- Has any reading arrived?
		do
			Result := update_count > 0
		end

	is_stale: BOOLEAN
			-- Is the data older than `stale_after' seconds, or is there none yet?
		do
			Result := update_count = 0 or else clock.now - received_at > stale_after
		end

	is_watching: BOOLEAN
			-- Is staleness re-checked periodically (`watch_staleness')?
		do
			Result := clock.pending_count > 0
		end

feature -- Element change

	watch_staleness (a_period: REAL_64)
			-- Re-check staleness every `a_period' seconds (a command on this signaler's processor,
			-- which wakes the clients waiting on it), so that `require s.is_stale' is woken when the
			-- topic goes silent. The checks keep the program running until `close' or `unwatch'.
		require
			positive: a_period > 0.0
		do
			clock.cancel
			clock.call_every (a_period, agent refresh)
		ensure
			watching: is_watching
		end

	unwatch
			-- Stop the periodic checks of `watch_staleness'.
		do
			clock.cancel
		ensure
			not_watching: not is_watching
		end

	set_stale_after (a_seconds: REAL_64)
			-- Let data go stale after `a_seconds' without a reading.
		require
			positive: a_seconds > 0.0
		do
			stale_after := a_seconds
		ensure
			set: stale_after = a_seconds
		end

	close
			-- Stop listening (no reading arrives any more) and watching.
		do
			clock.cancel
			across subscribers as s loop
				s.item.close
			end
		end

feature {NONE} -- Implementation

	refresh
			-- A periodic check of `watch_staleness': record what `is_stale' says now.
		do
			stale_checks := stale_checks + 1
			was_stale := is_stale
		end

	stale_checks: INTEGER
			-- Periodic checks so far.

	was_stale: BOOLEAN
			-- `is_stale' at the last periodic check.

	clock: TIMER
			-- The runtime's clock.

	subscribers: ARRAYED_LIST [ROS_SUBSCRIBER [ROS_MESSAGE]]
			-- Subscriptions feeding Current.

	note_reading
			-- A reading arrived now.
		do
			received_at := clock.now
			update_count := update_count + 1
		ensure
			counted: update_count = old update_count + 1
		end

	new_subscriber (a_topic: STRING): ROS_SUBSCRIBER [ROS_MESSAGE]
			-- A subscription to `a_topic', kept in `subscribers'.
		do
			create Result.make (a_topic)
			subscribers.extend (Result)
		ensure
			kept: subscribers.has (Result)
		end

end
