class
	BANK

feature -- Basic operations

	open (a_owner: STRING): ACCOUNT
			-- A new account for `a_owner'.
		do
			create Result.make (a_owner)
		end

end
