note
	description: "Root class using MONEY's operators and conversions."

class
	MONEY_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Exercise the operators.
		local
			a, b, c: MONEY
			r: REAL_64
		do
			create a.make (1_050)
			create b.make (275)
			c := a + b * 2 - -b
			print (c.out + "%N")
			c := +a // 3 + a \\ 3
			print (c.out + "%N")
			c := a |@| 15
			print (c.out + "%N")
			c := a + 3
			print (c.out + "%N")
			r := a
			print (r.out + "%N")
			print ((a < b).out + " " + (a >= b).out + " " + a.max (b).out + "%N")
			print ((a.plus (b) ~ a + b).out + "%N")
		end

end
