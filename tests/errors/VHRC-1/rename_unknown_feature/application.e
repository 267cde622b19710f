class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			d: PARROT
		do
			create d
			d.speak
		end

end
