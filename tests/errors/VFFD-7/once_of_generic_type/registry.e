class
	REGISTRY [G]

create
	make

feature {NONE} -- Initialization

	make
			-- An empty registry.
		do
		end

feature -- Access

	default_item: detachable G -- E: VFFD(7)
			-- One item shared by all registries.
		once
		end

	prototype: like Current -- E: VFFD(7)
			-- One registry shared by all.
		once
			create Result.make
		end

	own_copy: like Current
			-- One copy per registry.
		once ("OBJECT")
			create Result.make
		end

end
