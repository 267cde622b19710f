class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			b: BANK
			acc: ACCOUNT
		do
			create b
			print (b.open ("Ann").owner)
			create acc.make ("Bob") -- E: VGCC(6)
		end

end
