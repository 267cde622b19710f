deferred expanded class
	AMOUNT -- E: VTEC(1)

feature -- Access

	value: INTEGER
			-- The amount.
		deferred
		end

end
