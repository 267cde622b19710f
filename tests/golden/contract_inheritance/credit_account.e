class
	CREDIT_ACCOUNT

inherit
	BASE_ACCOUNT
		redefine
			withdraw,
			deposit,
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
			balance := balance - amount
			withdrawals := withdrawals + 1
		ensure then
			counted: withdrawals = old withdrawals + 1
		end

	deposit (amount: INTEGER)
		do
			Precursor (amount)
			deposits := deposits + 1
		end

	deposits: INTEGER

	fee: INTEGER
		do
			Result := Precursor + 5
		ensure then
			even: Result \\ 2 = 0
		end

	withdrawals: INTEGER

	force_debt (amount: INTEGER)
		do
			balance := balance - amount
		end

end
