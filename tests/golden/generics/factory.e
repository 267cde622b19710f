class
	FACTORY [G -> COUNTER create default_create, make_at end]

feature -- Creation

	new_default: G
		do
			create Result
		end

	new_at (v: INTEGER): G
		do
			create Result.make_at (v)
		end

end
