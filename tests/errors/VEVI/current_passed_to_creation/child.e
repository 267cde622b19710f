class
	CHILD

create
	make

feature {NONE} -- Initialization

	make (a_parent: APPLICATION)
			-- Keep `a_parent' and print its name's length: a qualified call.
		do
			parent := a_parent
			print (a_parent.name.count)
		end

feature -- Access

	parent: APPLICATION
			-- The object that made this one.

end
