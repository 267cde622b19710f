class
	BASE_ACCOUNT

feature -- Access

	balance: INTEGER
			-- Current balance.

	owner: STRING
			-- Who holds it.
		do
			Result := "anne"
		end

feature {NONE} -- Implementation

	audit_code: INTEGER = 7
			-- Hidden in this class.

end
