class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BIRD
		do
			create b
			b.speak
			b.fly
		end

end
