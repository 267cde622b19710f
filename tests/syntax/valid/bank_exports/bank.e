note
	description: "A bank: the only client that may create accounts and deposit."

class
	BANK

create
	make

feature {NONE} -- Initialization

	make
			-- Create a bank without accounts.
		do
			create accounts.make (3)
		end

feature -- Access

	accounts: ARRAYED_LIST [ACCOUNT]
			-- All accounts.

	total: INTEGER
			-- Sum of all balances.
		do
			across accounts as a loop
				Result := Result + a.item.balance
			end
		end

feature -- Operations

	open (owner: STRING; initial: INTEGER)
			-- Open an account with an initial deposit.
		local
			a: ACCOUNT
		do
			create a.make (owner)
			a.deposit (initial)
			accounts.extend (a)
		end

end
