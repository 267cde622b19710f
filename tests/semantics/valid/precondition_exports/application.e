note
	description: "Preconditions that use only features available to every client of their routine (VAPE)."

class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Open an account, use it and audit it.
		local
			auditor: AUDITOR
		do
			create account
			account.deposit (10)
			account.withdraw (3)
			create auditor
			auditor.audit (account)
			set_limit (5)
		end

	account: ACCOUNT
			-- The account.

	limit: INTEGER
			-- Secret.

	set_limit (n: INTEGER)
			-- A secret routine may require secret features.
		require
			above: n > limit
		do
			limit := n
		end

end
