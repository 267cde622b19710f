class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print (owner.age) -- E: VUTA(2)
		end

feature -- Access

	owner: detachable PERSON
			-- The owner, if known.

end
