note
	description: "Contracts: tagged and untagged preconditions and postconditions, old, class invariants."

class
	CONTRACTS_OLD

create
	make

feature {NONE} -- Initialization

	make
			-- Deposit and withdraw, checking contracts.
		do
			balance := 100
			deposit (50)
			withdraw (30)
			print (balance.out + "%N")
			print (transactions.out + "%N")
		end

feature -- Access

	balance: INTEGER
			-- Current balance.

	transactions: INTEGER
			-- Number of operations performed.

	overdraft_limit: INTEGER = 0
			-- How far below zero the balance may go.

feature -- Operations

	deposit (amount: INTEGER)
			-- Add `amount' to the balance.
		require
			positive_amount: amount > 0
			amount < 1_000_000
		do
			balance := balance + amount
			transactions := transactions + 1
		ensure
			increased: balance = old balance + amount
			counted: transactions = old transactions + 1
			balance > old balance
		end

	withdraw (amount: INTEGER)
			-- Take `amount' from the balance.
		require
			positive_amount: amount > 0;
			enough_money: balance - amount >= overdraft_limit
		do
			balance := balance - amount
			transactions := transactions + 1
		ensure
			decreased: balance = old balance - amount
			others_unchanged: old transactions < transactions and
				old (balance + amount) = balance + amount + amount
		end

	is_rich: BOOLEAN
			-- Is the balance large?
		do
			Result := balance > 1_000
		ensure
			definition: Result = (balance > 1_000)
		end

invariant
	balance_not_below_limit: balance >= overdraft_limit
	transactions_non_negative: transactions >= 0
	balance >= -1_000;
	consistent: is_rich implies balance > 0

end
