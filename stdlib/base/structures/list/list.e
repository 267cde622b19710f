note
	description: "Sequential lists, whatever their representation."

deferred class
	LIST [G]

inherit
	CHAIN [G]

feature -- Status report

	before: BOOLEAN
			-- Is `index' 0?
		do
			Result := index = 0
		end

	after: BOOLEAN
			-- Is `index' `count' + 1?
		do
			Result := index = count + 1
		end

end
