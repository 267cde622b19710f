class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			r: ROBOT
		do
			create r
			r.speak
		end

end
