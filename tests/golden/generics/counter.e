class
	COUNTER

inherit
	ANY
		redefine
			default_create
		end

create
	default_create,
	make_at

feature {NONE} -- Initialization

	default_create
		do
			value := 100
		end

	make_at (v: INTEGER)
		do
			value := v
		end

feature -- Access

	value: INTEGER

end
