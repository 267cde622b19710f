note
	description: "[
		One program, two robots: two Thymios (namespaces from ROBOT_ENVIRONMENT, `robot1' and
		`robot2' in the world) shuttle between two rooms through a passage too narrow for both.
		A shared PASSAGE_SIGNALER makes them take turns; each robot (a THYMIO_ROBOT) has its
		own odometry signaler, drive and SHUTTLE controller, on processors of their own. The mission stops
		one second before the run's end. With the argument `uncoordinated' the robots cross
		without asking (and meet in the passage).
	]"

class
	TWO_ROBOTS

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create each robot and its shuttle around one passage signaler; start them.
		local
			env: ROBOT_ENVIRONMENT
			i: INTEGER
			l_stop: separate STOP_SIGNALER
			l_passage: separate PASSAGE_SIGNALER
			robot: THYMIO_ROBOT
			l_shuttle: separate SHUTTLE
			coordinated: BOOLEAN
		do
			create env
			coordinated := index_of_word_option ("uncoordinated") = 0 and not
				(argument_count >= 1 and then argument (1).same_string ("uncoordinated"))
			if env.robot_count < 2 then
				io.error.put_string ("two_robots: the world must have two robots%N")
			else
				create l_stop.make
				create l_passage.make
				from
					i := 1
				until
					i > 2
				loop
					create robot.make_with_limits (env.namespace_of (i), env.max_linear_of (i), env.max_angular_of (i), False)
					create l_shuttle.make (i, robot.odometry, robot.drive, l_passage, l_stop, Passage_x, Passage_y,
						Speed.min (env.max_linear_of (i)), coordinated)
					start (l_shuttle)
					i := i + 1
				end
				if coordinated then
					print ("Mission: two robots, one passage, taking turns%N")
				else
					print ("Mission: two robots, one passage, uncoordinated%N")
				end
				if env.duration > Mission_margin then
					(create {TIMER}.make).sleep (env.duration - Mission_margin)
					end_mission (l_stop, l_passage)
				end
			end
		end

feature {NONE} -- Implementation

	start (a_shuttle: separate SHUTTLE)
			-- Let `a_shuttle' work.
		do
			a_shuttle.run
		end

	end_mission (a_stop: separate STOP_SIGNALER; a_passage: separate PASSAGE_SIGNALER)
			-- Stop both robots.
		do
			print ("Mission: over, " + a_passage.crossing_count.out + " crossing(s) granted%N")
			a_stop.request_stop
		end

feature {NONE} -- Constants

	Passage_x: REAL_64 = 2.0
	Passage_y: REAL_64 = 1.5
			-- Centre of the passage (world.yaml).

	Speed: REAL_64 = 0.12
			-- Largest forward speed (m/s).

	Mission_margin: REAL_64 = 1.0
			-- Seconds before the end of the run at which the mission stops.

end
