class
	ACCOUNT

create
	make

feature {NONE} -- Initialization

	make (a_owner: STRING)
			-- Open an account for `a_owner'.
		do
			owner := a_owner
			pin := 1234
		end

feature -- Access

	owner: STRING
			-- Holder of the account.

	balance: INTEGER
			-- Money in the account.

feature {BANK} -- Bank operations

	withdraw_all
			-- Empty the account.
		do
			balance := 0
		end

feature {NONE} -- Implementation

	pin: INTEGER
			-- Secret number.

end
