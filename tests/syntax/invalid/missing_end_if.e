note
	description: "The `if' in `make' has no `end': the parser notices at the next feature clause."

class
	MISSING_END_IF

create
	make

feature {NONE} -- Initialization

	make
			-- Print whether `limit' is large.
		do
			if limit > 10 then -- E: SYNTAX-END@4
				print ("large%N")
		end

feature -- Access

	limit: INTEGER = 20

end
