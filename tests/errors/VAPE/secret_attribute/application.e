class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Withdraw once.
		do
			balance := 10
			withdraw (3)
			print (balance.out + "%N")
		end

feature -- Access

	withdraw (amount: INTEGER)
			-- Take `amount' from the account.
		require
			positive: amount > 0
			enough: amount <= balance -- E: VAPE
			open: is_open -- E: VAPE
		do
			balance := balance - amount
		end

feature {AUDITOR} -- Auditing

	deposit (amount: INTEGER)
			-- Only AUDITOR may call it, and AUDITOR may test `is_open'.
		require
			open: is_open
		do
			balance := balance + amount
		end

feature {AUDITOR} -- Status

	is_open: BOOLEAN
			-- Open for AUDITOR's eyes.
		do
			Result := True
		end

feature {NONE} -- Implementation

	balance: INTEGER
			-- Secret.

end
