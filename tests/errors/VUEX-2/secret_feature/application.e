class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			acc: ACCOUNT
		do
			create acc.make ("Ann")
			print (acc.owner)
			print (acc.pin) -- E: VUEX(2)
		end

end
