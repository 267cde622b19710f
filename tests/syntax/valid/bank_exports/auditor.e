note
	description: "Auditors see balances and logs but cannot change them."

class
	AUDITOR

feature -- Audit

	report (b: BANK): STRING
			-- A line per account.
		do
			create Result.make_empty
			across b.accounts as a loop
				Result.append (a.item.owner + ": " + a.item.balance.out + " (" + a.item.log.count.out + " operations)%N")
			end
		end

end
