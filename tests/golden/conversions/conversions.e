note
	description: "Conversions: convert clauses of a user class, numeric promotions, explicit conversion queries."

class
	CONVERSIONS

create
	make

feature {NONE} -- Initialization

	make
		local
			c: CELSIUS
			k: REAL_64
			d: REAL_64
			i: INTEGER
			big: INTEGER_64
			small: INTEGER_8
			n: NATURAL_32
			f: REAL_32
		do
			c := 21
			print ("from INTEGER: " + c.out + "%N")
			k := c
			print ("to REAL_64: " + k.out + "%N")
			show (30)
			print ("sum: " + (kelvin (c) + kelvin (create {CELSIUS}.make (-273.15))).out + "%N")
			i := 7
			d := i
			big := i
			f := i
			print ("promotions: " + d.out + " " + big.out + " " + f.out + " " + (i / 2).out + " " + (i + 0.5).out + "%N")
			small := 100
			print ("INTEGER_8 + INTEGER: " + (small + 1000).out + "%N")
			n := 4_000_000_000
			print ("NATURAL_32 to INTEGER_64: " + (n.to_integer_64 + 1).out + "%N")
			print ("explicit: " + (3.99).truncated_to_integer.out + " " + (-3.5).rounded.out + " " + (65).to_character_8.out + " " + ('A').code.out + "%N")
		end

feature {NONE} -- Implementation

	show (c: CELSIUS)
		do
			print ("argument converted: " + c.out + "%N")
		end

	kelvin (k: REAL_64): REAL_64
		do
			Result := k
		end

end
