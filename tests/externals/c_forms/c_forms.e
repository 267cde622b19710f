note
	description: "EiffelStudio's forms of C and C++ externals, with a C source and header of the program's own named in the .ecf."

class
	C_FORMS

create
	make

feature

	make
		local
			a: ARRAY [REAL_64]
		do
			print (c_sin (0.0).out + " " + c_cos (0.0).out + " " + twice (21).out + "%N")
			a := <<1.0, 2.0, 6.0>>
			print (mean (a, a.count).out + "%N")
			scale (a, a.count, 10.0)
			print (a [3].out + "%N")
			print (larger (3, 9).out + " " + is_positive (-2).out + " " + upper ('q').out + "%N")
			print (describe ("abc") + "%N")
			print (byte_count ("é").out + " " + byte_count_32 ({STRING_32} "é").out + " " + e_acute.count.out + " " + e_acute_32.count.out + "%N")
			print ((address /= default_pointer).out + "%N")
		end

feature -- Externals

	c_sin (x: REAL_64): REAL_64 external "C signature (DOUBLE): DOUBLE use <math.h>" alias "sin" end
	c_cos (x: REAL_64): REAL_64 external "C inline use <math.h>" alias "return cos ($x);" end
	twice (x: INTEGER): INTEGER external "C inline" alias "$x * 2" end
	mean (a: ARRAY [REAL_64]; n: INTEGER): REAL_64 external "C use %"stats.h%"" alias "stats_mean" end
	scale (a: ARRAY [REAL_64]; n: INTEGER; f: REAL_64) external "C (double *, EIF_INTEGER, double) | %"stats.h%"" alias "stats_scale" end
	larger (a, b: INTEGER): INTEGER external "C++ inline use <algorithm>" alias "return std::max ($a, $b);" end
	is_positive (x: INTEGER): BOOLEAN external "C inline" alias "$x > 0" end
	upper (c: CHARACTER): CHARACTER external "C inline use <ctype.h>" alias "return (char) toupper ($c);" end
	describe (s: STRING): STRING external "C inline use <string.h>" alias "return strlen ($s) == 3 ? %"three%" : %"other%";" end
	byte_count (s: STRING): INTEGER external "C inline use <string.h>" alias "return (int) strlen ($s);" end
	byte_count_32 (s: STRING_32): INTEGER external "C inline use <string.h>" alias "return (int) strlen ($s);" end
	e_acute: STRING external "C inline" alias "return %"\xc3\xa9%";" end
	e_acute_32: STRING_32 external "C inline" alias "return %"\xc3\xa9%";" end
	address: POINTER external "C inline use <stdlib.h>" alias "return (void *) &malloc;" end

end
