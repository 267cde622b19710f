note
	description: "A class invariant violated after a qualified call: the program fails (exit 3, trace on stderr)."

class
	INVARIANT_FAILURE

create
	make

feature {NONE} -- Initialization

	make
		local
			acc: ACCOUNT
		do
			create acc.make (100)
			acc.withdraw (30)
			print ("balance " + acc.balance.out + "%N")
			acc.withdraw (100)
			print ("not reached%N")
		end

end
