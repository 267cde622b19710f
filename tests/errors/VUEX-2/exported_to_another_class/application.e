class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			acc: ACCOUNT
			b: BANK
		do
			create acc.make ("Ann")
			create b
			b.close (acc)
			acc.withdraw_all -- E: VUEX(2)
		end

end
