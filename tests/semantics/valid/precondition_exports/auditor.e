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
		end

end
