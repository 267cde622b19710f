note
	description: "[
		A narrow passage that one robot at a time may use: robots wait for `is_free' in a
		wait condition, then `enter' and later `leave'. Shared by the robots' controllers,
		each on its own processor.
	]"

class
	PASSAGE_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- A free passage.
		do
		ensure
			free: is_free
		end

feature -- Access

	holder: INTEGER
			-- The robot in the passage (0: none).

	crossing_count: INTEGER
			-- Crossings started so far.

feature -- Status report

	is_free: BOOLEAN
			-- May a robot enter?
		do
			Result := holder = 0
		end

feature -- Element change

	enter (a_robot: INTEGER)
			-- Let robot `a_robot' into the passage.
		require
			valid_robot: a_robot > 0
			free: is_free
		do
			holder := a_robot
			crossing_count := crossing_count + 1
		ensure
			held: holder = a_robot
			counted: crossing_count = old crossing_count + 1
		end

	leave (a_robot: INTEGER)
			-- Robot `a_robot' is out of the passage.
		require
			holder: holder = a_robot
		do
			holder := 0
		ensure
			free: is_free
		end

invariant
	valid_holder: holder >= 0
	counted: crossing_count >= 0

end
