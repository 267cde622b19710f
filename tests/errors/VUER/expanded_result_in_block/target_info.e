note
	description: "What is known of a tracked target, copied on assignment."

expanded class
	TARGET_INFO

inherit
	ANY
		redefine
			default_create
		end

feature -- Initialization

	default_create
			-- No target.
		do
			name := "nothing"
		end

feature -- Access

	name: STRING
			-- What the target is.

	distance: INTEGER
			-- How far it is, in centimetres.

feature -- Element change

	set (a_name: STRING; a_distance: INTEGER)
			-- Target `a_name' at `a_distance'.
		do
			name := a_name
			distance := a_distance
		end

end
