note
	description: "An account: its exported routines require exported features, the routines for AUDITOR %
		%also features exported to AUDITOR only."

class
	ACCOUNT

feature -- Access

	balance: INTEGER
			-- Current balance.

	withdraw (amount: INTEGER)
			-- Take `amount'.
		require
			positive: amount > 0
			enough: amount <= balance
		do
			balance := balance - amount
		end

	deposit (amount: INTEGER)
			-- Add `amount'.
		require
			positive: amount > 0
		do
			balance := balance + amount
		end

feature {AUDITOR} -- Auditing

	is_frozen: BOOLEAN
			-- Frozen by an auditor?

	unfreeze
			-- Let the account be used again.
		require
			is_frozen: is_frozen
			audited: audits > 0
		do
			is_frozen := False
		end

	freeze
			-- Stop withdrawals.
		do
			is_frozen := True
			audits := audits + 1
		end

	audits: INTEGER
			-- Audits so far.

end
