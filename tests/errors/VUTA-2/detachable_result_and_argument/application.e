class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print (found.age) -- E: VUTA(2)
			show (found)
		end

feature -- Access

	found: detachable PERSON
			-- A person, if one is found.
		do
			create Result
		end

feature -- Output

	show (a_person: detachable PERSON)
			-- Print the age of `a_person'.
		do
			print (a_person.age) -- E: VUTA(2)
			if attached a_person as p then
				print (p.age)
			end
		end

end
