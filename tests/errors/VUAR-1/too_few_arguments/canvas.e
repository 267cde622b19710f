class
	CANVAS

create
	make

feature {NONE} -- Initialization

	make (a_width, a_height: INTEGER)
			-- Create a canvas of the given size.
		do
			width := a_width
			height := a_height
		end

feature -- Access

	width, height: INTEGER
			-- Size.

end
