note
	description: "Bank accounts whose features are exported selectively."

class
	ACCOUNT

create {BANK}
	make

feature {NONE} -- Initialization

	make (an_owner: STRING)
			-- Open an account for `an_owner'.
		do
			owner := an_owner
		end

feature -- Access

	owner: STRING
			-- Who holds the account.

feature {BANK, AUDITOR} -- Balance

	balance: INTEGER
			-- Money in the account.

feature {BANK} -- Element change

	deposit (amount: INTEGER)
			-- Add `amount'.
		require
			positive: amount > 0
		do
			balance := balance + amount
			log.extend ("deposit " + amount.out)
		end

feature {AUDITOR} -- Audit

	log: ARRAYED_LIST [STRING]
			-- Every operation.
		attribute
			create Result.make (10)
		end

feature {NONE} -- Implementation

	secret_pin: INTEGER = 1234
			-- Known only to the account itself.

feature {ANY} -- Status

	is_open: BOOLEAN = True
			-- Accounts never close in this example.

feature {} -- Nothing

	internal_note: STRING = "an empty export list means {NONE}"

end
