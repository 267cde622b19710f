expanded class
	SIZE

create
	default_create, make

feature {NONE} -- Initialization

	make (a_width: INTEGER)
			-- A size of `a_width'.
		do
			width := a_width
		end

feature -- Access

	width: INTEGER
			-- Width.

end
