class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Build factories.
		local
			widgets: FACTORY [WIDGET]
			gadgets: FACTORY [GADGET] -- E: VTCG
		do
			create widgets
			print (widgets.produced (1).generating_type.out + "%N")
		end

end
