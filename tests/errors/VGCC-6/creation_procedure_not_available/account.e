class
	ACCOUNT

create {BANK}
	make

feature {NONE} -- Initialization

	make (a_owner: STRING)
			-- Open an account for `a_owner'.
		do
			owner := a_owner
		end

feature -- Access

	owner: STRING
			-- Holder of the account.

end
