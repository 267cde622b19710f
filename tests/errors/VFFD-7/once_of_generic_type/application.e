class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a registry.
		local
			r: REGISTRY [STRING]
		do
			create r.make
			print (r.own_copy.generating_type.out + "%N")
		end

end
