class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Nothing to do.
		do
			print ("amounts%N")
		end

end
