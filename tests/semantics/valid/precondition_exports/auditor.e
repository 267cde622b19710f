note
	description: "A client with access to ACCOUNT's auditing features."

class
	AUDITOR

feature -- Auditing

	audit (a: ACCOUNT)
			-- Freeze `a' and let it go again.
		do
			a.freeze
			if a.is_frozen then
				a.unfreeze
			end
			print (a.balance.out + "%N")
			release (a)
			report (a)
		end

	report (a: ACCOUNT)
			-- Print `a''s balance: its precondition calls an exported feature of ACCOUNT.
		require
			solvent: a.balance >= 0
		do
			print (a.balance.out + "%N")
		end

feature {AUDITOR} -- Auditing

	release (a: ACCOUNT)
			-- For auditors only, whose precondition may call ACCOUNT's features for AUDITOR.
		require
			frozen_once: a.audits > 0
		do
			if a.is_frozen then
				a.unfreeze
			end
		end

end
