note
	description: "Real literals: plain, with exponents, with underscores, typed."

class
	LITERALS_REAL

create
	make

feature {NONE} -- Initialization

	make
			-- Print reals written in several ways.
		local
			x: REAL_64
			y: REAL_32
		do
			x := 3.14159
			print (x.out + "%N")
			x := 1.5e10
			print (x.out + "%N")
			x := 2.5E-3
			print (x.out + "%N")
			x := 6.022_140_76e+23
			print (x.out + "%N")
			x := 1_000.000_1
			print (x.out + "%N")
			x := 0.5
			print (x.out + "%N")
			x := -273.15
			print (x.out + "%N")
			x := 1.
			print (x.out + "%N")
			x := .25
			print (x.out + "%N")
			y := {REAL_32} 1.5
			print (y.out + "%N")
			x := {REAL_64} 10.0
			print (x.out + "%N")
			x := 7 / 2
			print (x.out + "%N")
			x := 2.0 ^ 10
			print (x.out + "%N")
		end

end
