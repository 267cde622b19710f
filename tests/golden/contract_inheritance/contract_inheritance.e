note
	description: "Contracts under redefinition: require else, ensure then, Precursor with arguments, inherited invariants."

class
	CONTRACT_INHERITANCE

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			acc: CREDIT_ACCOUNT
			base: BASE_ACCOUNT
		do
			create acc.make (50)
			acc.withdraw (120)
			print ("credit withdrawal: " + acc.balance.out + " after " + acc.withdrawals.out + "%N")
			acc.deposit (60)
			print ("deposit through Precursor: " + acc.balance.out + " deposits " + acc.deposits.out + "%N")
			base := acc
			print (attempt (agent base.withdraw (40)) + "%N")
			print (attempt (agent base.withdraw (100)) + "%N")
			print (attempt (agent base.deposit (0)) + "%N")
			print (attempt (agent base.fee) + "%N")
			print (attempt (agent acc.force_debt (500)) + "%N")
		end

feature {NONE} -- Implementation

	attempt (action: ROUTINE): STRING
		local
			failed: BOOLEAN
		do
			if failed then
				Result := "failed"
				if attached exception_manager.last_exception as e then
					Result := Result + ": " + e.original.generator
				end
			else
				action.apply
				Result := "done"
			end
		rescue
			failed := True
			retry
		end

end
