class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			d: DOG
		do
			create d
			d.speak
		end

end
