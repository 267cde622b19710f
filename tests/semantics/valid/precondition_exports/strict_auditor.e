note
	description: "An heir that redeclares `release' with the same export: its inherited precondition %
		%calls features available to all its clients (VAPE checked in the heir)."

class
	STRICT_AUDITOR

inherit
	AUDITOR
		redefine
			release
		end

feature {AUDITOR} -- Auditing

	release (a: ACCOUNT)
			-- Release only an account with a positive balance.
		do
			if a.balance > 0 and a.is_frozen then
				a.unfreeze
			end
		end

end
