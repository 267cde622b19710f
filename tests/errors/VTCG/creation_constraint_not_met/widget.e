class
	WIDGET

create
	make, make_named

feature {NONE} -- Initialization

	make
			-- A widget.
		do
		end

	make_named (a_name: STRING)
			-- A widget called `a_name'.
		do
		end

end
