class
	APPLICATION -- E: VSRP(1)

create
	make

feature -- Initialization

	make
			-- Create.
		do
			print ("make%N")
		end

	start
			-- Not listed after `create`.
		do
			print ("start%N")
		end

end
