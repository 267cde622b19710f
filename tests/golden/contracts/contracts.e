note
	description: "Preconditions, postconditions with `old', class invariants: violations seen by a rescue clause."

class
	CONTRACTS

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			acc: ACCOUNT
		do
			create acc.make (100)
			acc.deposit (50)
			acc.withdraw (30)
			print ("balance " + acc.balance.out + " doubled " + acc.doubled.out + " history " + acc.history.count.out + "%N")
			try (acc, "deposit zero")
			try (acc, "overdraw")
			try (acc, "faulty deposit")
			print ("balance " + acc.balance.out + "%N")
			try (acc, "negative opening")
		end

feature {NONE} -- Implementation

	try (acc: ACCOUNT; what: STRING)
		local
			failed: BOOLEAN
			other: ACCOUNT
		do
			if not failed then
				if what ~ "deposit zero" then
					acc.deposit (0)
				elseif what ~ "overdraw" then
					acc.withdraw (1000)
				elseif what ~ "faulty deposit" then
					acc.faulty_deposit (10)
				else
					create other.make (-5)
				end
				print (what + ": accepted%N")
			end
		rescue
			if attached exception_manager.last_exception as e then
				print (what + ": " + e.original.generator + " " + e.original.tag + "%N")
			end
			failed := True
			retry
		end

end
