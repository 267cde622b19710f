class
	SQUARE -- E: VCCH(1)

inherit
	SHAPE

feature -- Access

	side: INTEGER
			-- Length of a side.

end
