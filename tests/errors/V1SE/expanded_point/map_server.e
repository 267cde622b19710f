note
	description: "Keeps the marks put on a map."

class
	MAP_SERVER

create
	make

feature {NONE} -- Initialization

	make
			-- Map with no mark.
		do
			marks := 0
		end

feature -- Access

	marks: INTEGER
			-- Number of marks.

	last_x, last_y: REAL_64
			-- Coordinates of the last mark.

feature -- Element change

	mark (a_x, a_y: REAL_64)
			-- Put a mark at (`a_x', `a_y').
		do
			marks := marks + 1
			last_x := a_x
			last_y := a_y
		end

end
