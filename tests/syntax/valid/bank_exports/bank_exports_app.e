note
	description: "Root class of the bank program."

class
	BANK_EXPORTS_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Open accounts and audit them.
		local
			bank: BANK
			auditor: AUDITOR
		do
			create bank.make
			bank.open ("ada", 100)
			bank.open ("alan", 250)
			create auditor
			print (auditor.report (bank))
			print (bank.total.out + " " + bank.accounts.first.owner + " " + bank.accounts.first.is_open.out + "%N")
		end

end
