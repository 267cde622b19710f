class
	STALE_APP

create
	make

feature

	make
			-- Odometry and a group of two range topics: fresh after a message, stale once silent;
			-- a wait condition on `is_stale' woken by `watch_staleness'.
		local
			odom: separate ODOMETRY_SIGNALER
			group: separate GROUP_SIGNALER
			clock: TIMER
			watched: separate ODOMETRY_SIGNALER
		do
			create clock.make
			create odom.make ("/odom")
			create group.make
			create watched.make ("/odom2")
			add (group, "/range/a")
			add (group, "/range/b")
			show ("start", odom, group)
			await (odom, group, watched)
			watch (watched)
			show ("fresh", odom, group)
			clock.sleep (0.3)
			show ("after 0.3 s", odom, group)
			await_stale (watched)
			print ("watched odometry stale at " + clock.now.out + "%N")
			clock.sleep (0.1)
			show ("after 0.7 s", odom, group)
			close (odom, group)
			close_watched (watched)
		end

	add (g: separate GROUP_SIGNALER; t: STRING)
		do
			g.add_range (t)
		end

	watch (o: separate ODOMETRY_SIGNALER)
		do
			o.watch_staleness (0.1)
		end

	await_stale (o: separate ODOMETRY_SIGNALER)
		require
			o.has_reading and o.is_stale
		do
		end

	close_watched (o: separate ODOMETRY_SIGNALER)
		do
			o.close
		end

	await (o: separate ODOMETRY_SIGNALER; g: separate GROUP_SIGNALER; w: separate ODOMETRY_SIGNALER)
		require
			o.has_reading
			w.has_reading
			not g.is_sensor_stale (0)
			not g.is_sensor_stale (1)
		do
		end

	show (what: STRING; o: separate ODOMETRY_SIGNALER; g: separate GROUP_SIGNALER)
		do
			print (what + ": odometry stale " + o.is_stale.out + ", group stale " + g.is_stale.out
				+ ", nearest " + g.nearest.out + " (sensor " + g.nearest_sensor.out + "), below 0.1: "
				+ g.count_below (0.1).out + "%N")
		end

	close (o: separate ODOMETRY_SIGNALER; g: separate GROUP_SIGNALER)
		do
			o.close
			g.close
		end

end
