class
	EXPORT_ALL
		-- Export clauses over three levels: a listed feature keeps its clients whatever
		-- `all` says, wherever it stands in the clause; `{ANY} all' opens even secret features.

create
	make

feature {NONE} -- Initialization

	make
			-- Use each account.
		local
			l_locked: LOCKED_ACCOUNT
			l_open: OPEN_ACCOUNT
			l_family: FAMILY_ACCOUNT
		do
			create l_locked
			create l_open
			create l_family
			print (l_locked.balance)
			print (l_open.owner)
			print (l_open.audit_code)
			print (l_family.owner)
		end

end
