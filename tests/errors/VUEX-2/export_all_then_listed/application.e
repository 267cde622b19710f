class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use features hidden by `{NONE} all' and by a list naming other clients.
		local
			l_locked: LOCKED_ACCOUNT
			l_shared: SHARED_ACCOUNT
		do
			create l_locked
			create l_shared
			print (l_locked.owner) -- E: VUEX(2)
			print (l_shared.owner) -- E: VUEX(2)
			print (l_shared.balance)
		end

end
