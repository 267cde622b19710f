class
	ACCOUNT

create
	make

feature {NONE} -- Initialization

	make (initial: INTEGER)
		do
			balance := initial
		end

feature -- Access

	balance: INTEGER

feature -- Operations

	withdraw (amount: INTEGER)
			-- No precondition: the invariant catches overdrafts.
		do
			balance := balance - amount
		end

invariant
	non_negative_balance: balance >= 0

end
