class
	AUDITOR

feature -- Basic operations

	check_account (a: APPLICATION)
			-- Look at `a'.
		do
			if a.is_open then
				print ("open%N")
			end
		end

end
