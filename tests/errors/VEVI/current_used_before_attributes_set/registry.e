class
	REGISTRY

create
	make

feature {NONE} -- Initialization

	make
			-- An empty registry.
		do
			create entries.make (4)
		end

feature -- Element change

	add (a: ANY)
			-- Remember `a'.
		do
			entries.extend (a)
		end

feature -- Access

	entries: ARRAYED_LIST [ANY]
			-- Registered objects.

end
