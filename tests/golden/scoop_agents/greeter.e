class
	GREETER

feature -- Access

	greetings: INTEGER

	last: STRING
		attribute
			Result := ""
		end

	partner: detachable separate GREETER

feature -- Change

	greet (name: separate STRING)
		do
			greetings := greetings + 1
			create last.make_from_separate (name)
			print ("hello " + last + "%N")
		end

	set_partner (p: separate GREETER)
		do
			partner := p
		end

	new_greeter: separate GREETER
			-- A greeter on a new processor.
		do
			create Result
		end

end
