class
	CREATURE

feature -- Access

	legs: INTEGER
			-- Number of legs.
		do
			Result := 4
		end

feature -- Basic operations

	eat (food: STRING)
			-- Eat `food'.
		do
			print ("eating " + food + "%N")
		end

end
