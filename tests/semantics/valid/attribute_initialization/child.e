class
	CHILD

create
	make

feature {NONE} -- Initialization

	make (a_parent: APPLICATION)
			-- Keep `a_parent' (no qualified call: valid while its attributes are still unset).
		do
			parent := a_parent
		end

feature -- Access

	parent: APPLICATION
			-- The object that made this one.

end
