class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			c: CAT
		do
			create c
			c.speak
		end

end
