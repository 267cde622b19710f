class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Create a child that reads this object's `name' before it is set.
		do
			create child.make (Current) -- E: VEVI@23
			name := "scoop"
		end

feature -- Access

	name: STRING
			-- Set after the child is created.

	child: CHILD
			-- Made with a reference to this object.

end
