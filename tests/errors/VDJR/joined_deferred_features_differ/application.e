class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Nothing to run.
		do
			print ("tiles%N")
		end

end
