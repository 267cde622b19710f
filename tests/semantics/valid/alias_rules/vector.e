class
	VECTOR

inherit
	SUMMABLE
	MERGEABLE
		rename
			merged as merged_with alias "|+|"
		end

feature -- Access

	x: INTEGER
			-- A coordinate.

end
