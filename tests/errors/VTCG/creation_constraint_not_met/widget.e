class
	WIDGET

inherit
	PRODUCT

create
	make, make_named

feature {NONE} -- Initialization

	make_named (a_name: STRING)
			-- A widget called `a_name'.
		do
		end

end
