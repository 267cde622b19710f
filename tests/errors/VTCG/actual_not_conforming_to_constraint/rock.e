class
	ROCK

feature -- Access

	weight: INTEGER
			-- Weight in grams.

end
