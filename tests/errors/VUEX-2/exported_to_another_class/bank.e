class
	BANK

feature -- Basic operations

	close (a_account: ACCOUNT)
			-- Close `a_account'.
		do
			a_account.withdraw_all
		end

end
