class
	CREDIT_ACCOUNT

inherit
	BASE_ACCOUNT
		redefine
			withdraw,
			fee
		end

create
	make

feature -- Operations

	withdraw (amount: INTEGER)
			-- May go into debt, up to the credit line.
		require else
			within_credit: amount <= balance + 100
		do
			Precursor {BASE_ACCOUNT} (amount)
			withdrawals := withdrawals + 1
		ensure then
			counted: withdrawals = old withdrawals + 1
		end

	fee: INTEGER
		do
			Result := Precursor + 6
		ensure then
			even: Result \\ 2 = 0
		end

	withdrawals: INTEGER

	force_debt (amount: INTEGER)
		do
			balance := balance - amount
		end

end
