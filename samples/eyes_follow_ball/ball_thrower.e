note
	description: "[
		Stand-in for the world: somebody who throws the ball somewhere new each time the
		robot has found it, and finally puts it away.
	]"

class
	BALL_THROWER

create
	make

feature {NONE} -- Initialization

	make (a_ball: separate BALL_SIGNALER; a_head: separate HEAD)
			-- Thrower moving `a_ball' and watching `a_head'.
		do
			ball := a_ball
			head := a_head
		end

feature -- Basic operations

	play
			-- Throw the ball to each place in turn, then put it away.
		do
			across Throws as c loop
				throw (ball, head, c.item)
				(create {EXECUTION_ENVIRONMENT}).sleep (Pause)
			end
			put_away (ball, head)
		end

feature {NONE} -- Implementation

	throw (a_ball: separate BALL_SIGNALER; a_head: separate HEAD; a_bearing: INTEGER)
			-- Once the robot looks at `a_ball', throw it to `a_bearing'.
		require
			robot_looks_at_ball: a_head.is_facing (a_ball.bearing)
		do
			a_ball.publish (a_bearing)
			print ("Thrower: ball thrown to " + a_bearing.out + " degrees%N")
		ensure
			thrown: a_ball.bearing = a_bearing
		end

	put_away (a_ball: separate BALL_SIGNALER; a_head: separate HEAD)
			-- Once the robot looks at `a_ball', take it out of the game.
		require
			robot_looks_at_ball: a_head.is_facing (a_ball.bearing)
		do
			a_ball.put_away
			print ("Thrower: ball put away%N")
		end

	ball: separate BALL_SIGNALER
			-- The ball.

	head: separate HEAD
			-- The robot's head, watched to see whether it found the ball.

	Throws: ARRAY [INTEGER]
			-- Where the ball goes, in degrees: the head can follow only up to 45 either way.
		once
			Result := <<30, -20, 60, -60, 10>>
		end

	Pause: INTEGER_64 = 10_000_000
			-- Time between two throws, in nanoseconds.

end
