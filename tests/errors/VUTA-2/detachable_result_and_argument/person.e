class
	PERSON

feature -- Access

	age: INTEGER
			-- Age in years.

end
