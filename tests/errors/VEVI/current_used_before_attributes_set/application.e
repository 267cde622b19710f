class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Register with a registry before `name' is set.
		do
			create registry.make
			registry.add (Current) -- E: VEVI@18
			name := "scoop"
		end

feature -- Access

	name: STRING
			-- Set after `Current' was handed out.

	registry: REGISTRY
			-- Where this object registers.

end
