class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Nothing.
		do
		end

end
