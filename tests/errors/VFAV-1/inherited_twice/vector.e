class
	VECTOR -- E: VFAV(1)

inherit
	SUMMABLE
	MERGEABLE

feature -- Access

	x: INTEGER
			-- A coordinate.

end
