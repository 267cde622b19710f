class
	GADGET

inherit
	PRODUCT

create
	make_small

feature {NONE} -- Initialization

	make_small
			-- A small gadget.
		do
		end

end
