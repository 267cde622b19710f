class
	DINER

create
	make

feature

	make (i: INTEGER; a, b: separate PLATE)
		do
			id := i
			first := a
			second := b
		end

	id: INTEGER

	dine (n: INTEGER)
		do
			across 1 |..| n as k loop
				eat (first, second)
			end
		end

feature {NONE}

	first, second: separate PLATE

	eat (a, b: separate PLATE)
		do
			a.take (Current)
			b.take (Current)
			a.give_back (Current)
			b.give_back (Current)
		end

end
