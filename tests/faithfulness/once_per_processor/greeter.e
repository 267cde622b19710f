class
	GREETER

create
	make

feature

	make (i: INTEGER)
		do
			id := i
		end

	id: INTEGER

	name: STRING
			-- Computed once per processor: the first greeter of this processor names it.
		once
			Result := "greeter-" + id.out
		end

	shared: INTEGER
			-- Computed once for the whole program: the id of the first greeter to ask.
		once ("PROCESS")
			Result := id
		end

	greet
		do
			print (name + " shared " + shared.out + "%N")
		end

end
