class
	CLICKER

create
	make

feature {NONE} -- Initialization

	make (t: separate TALLY; n: separate STRING)
		do
			tally := t
			create name.make_from_separate (n)
		end

feature -- Basic operations

	run
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > 50
			loop
				click (tally)
				i := i + 1
			end
			print (name + " done%N")
		end

feature {NONE} -- Implementation

	tally: separate TALLY

	name: STRING

	click (t: separate TALLY)
		do
			t.increment
		end

end
