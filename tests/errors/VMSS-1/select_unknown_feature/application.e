class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			p: PARROT
		do
			create p
			p.speak
		end

end
