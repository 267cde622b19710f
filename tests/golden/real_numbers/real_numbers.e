note
	description: "REAL_64 and REAL_32 arithmetic, conversions and `out' (17 and 6 significant digits)."

class
	REAL_NUMBERS

create
	make

feature {NONE} -- Initialization

	make
		local
			r, s: REAL_64
			f, g: REAL_32
			i: INTEGER
			m: DOUBLE_MATH
			zero: REAL_64
			none: INTEGER
		do
			r := 0.1
			s := 0.2
			show ("0.1 + 0.2", (r + s).out)
			show ("0.1 + 0.2 = 0.3", (r + s = 0.3).out)
			show ("1 / 3", (1 / 3).out)
			show ("3.0", (3.0).out)
			show ("2.5 * 4", (2.5 * 4).out)
			show ("1.0e20", (1.0e20).out)
			show ("1.5e-7", (1.5e-7).out)
			show ("-2.75", (-2.75).out)
			show ("r + 1", (r + 1).out)
			show ("r * 3", (r * 3).out)
			show ("10 / 4", (10 / 4).out)
			f := 0.1
			show ("f 0.1", f.out)
			show ("f to_double", f.to_double.out)
			g := 3.0
			show ("f / 3", (f / g).out)
			from
				i := 1
				g := 0.0
			until
				i > 10
			loop
				g := g + f
				i := i + 1
			end
			show ("ten times f", g.out + " " + g.to_double.out)
			f := 16777216.0
			show ("f + 1 = f", (f + 1 = f).out + " " + (f + 1).out)
			f := 1234567.0
			show ("f 1234567", f.out)
			show ("truncated", (2.7).truncated_to_integer.out + " " + (-2.7).truncated_to_integer.out)
			show ("floor, ceiling", (-2.5).floor.out + " " + (-2.5).ceiling.out)
			show ("rounded", (2.5).rounded.out + " " + (-2.5).rounded.out + " " + (2.4).rounded.out)
			show ("2.0 ^ 0.5", (2.0 ^ 0.5).out)
			show ("abs, max, min", (-1.5).abs.out + " " + (1.5).max (2.5).out + " " + (1.5).min (2.5).out)
			show ("comparisons", (1.5 < 2.5).out + " " + (1.5 >= 2.5).out)
			show ("integer to real", (7).to_double.out + " " + (7).to_real.out)
			create m
			show ("sqrt 2", m.sqrt (2.0).out)
			show ("pi", m.pi.out)
			show ("floor_real_64", (2.5).floor_real_64.out)
			show ("100.0 / 7", (100.0 / 7).out)
			show ("1e16 + 1", (1.0e16 + 1).out)
			show ("0.000123", (0.000123).out)
			show ("123456789012.0", (123456789012.0).out)
			show ("division by zero", (1.0 / zero).out + " " + (-1.0 / zero).out + " " + (zero / zero).is_nan.out + " " + (7 / none).out)
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
