class
	ACCUMULATOR

create
	make

feature {NONE} -- Initialization

	make (n: separate STRING)
		do
			create name.make_from_separate (n)
			print ("created " + name + "%N")
		end

feature -- Access

	name: STRING

	sum: INTEGER

feature -- Change

	add (v: INTEGER)
		do
			sum := sum + v
			print (name + " + " + v.out + " = " + sum.out + "%N")
		end

end
