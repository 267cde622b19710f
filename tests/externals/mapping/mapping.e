note
	description: "Every mapping of an external %"Python%": basic types, strings, arrays and specials of numbers, opaque handles."

class
	MAPPING

create
	make

feature

	make
		local
			a: ARRAY [REAL_64]
			s: SPECIAL [INTEGER_32]
			h: POINTER
		do
			print (twice (21).out + " " + twice_64 (4_000_000_000).out + " " + half (3.0).out + "%N")
			print (negate (True).out + " " + next_char ('a').out + " " + natural_max.out + "%N")
			print (greet ("Eiffel") + " ")
			print (greet_32 ({STRING_32} "Ω").count.out + " " + greet_32 ({STRING_32} "Ω").item (7).code.out + "%N")
			print (greet ("é").count.out + " " + text_length ("é").out + " " + text_length_32 ({STRING_32} "é").out + "%N")
			a := <<1.0, 2.0, 3.0>>
			scale (a, 2.0)
			print (a [1].out + " " + a [3].out + " " + total (a).out + "%N")
			create s.make_filled (1, 4)
			s.put (5, 2)
			print (special_sum (s).out + "%N")
			a := ramp (4)
			print (a.lower.out + ".." + a.upper.out + " " + a [4].out + "%N")
			s := squares (3)
			print (s.count.out + " " + s [2].out + "%N")
			h := new_counter (5)
			bump (h)
			bump (h)
			print (counter_value (h).out + "%N")
			if nothing = Void then
				print ("Void%N")
			end
		end

feature -- Externals

	twice (x: INTEGER): INTEGER external "Python" alias "mapping_mod.twice" end
	twice_64 (x: INTEGER_64): INTEGER_64 external "Python" alias "mapping_mod.twice" end
	half (x: REAL_64): REAL_64 external "Python" alias "mapping_mod.half" end
	negate (b: BOOLEAN): BOOLEAN external "Python" alias "mapping_mod.negate" end
	next_char (c: CHARACTER): CHARACTER external "Python" alias "mapping_mod.next_char" end
	natural_max: NATURAL_8 external "Python" alias "mapping_mod.natural_max" end
	greet (s: STRING): STRING external "Python" alias "mapping_mod.greet" end
	greet_32 (s: STRING_32): STRING_32 external "Python" alias "mapping_mod.greet" end
	text_length (s: STRING): INTEGER external "Python" alias "builtins.len" end
	text_length_32 (s: STRING_32): INTEGER external "Python" alias "builtins.len" end
	scale (a: ARRAY [REAL_64]; f: REAL_64) external "Python" alias "mapping_mod.scale" end
	total (a: ARRAY [REAL_64]): REAL_64 external "Python" alias "numpy.sum" end
	special_sum (s: SPECIAL [INTEGER_32]): INTEGER external "Python" alias "mapping_mod.special_sum" end
	ramp (n: INTEGER): ARRAY [REAL_64] external "Python" alias "mapping_mod.ramp" end
	squares (n: INTEGER): SPECIAL [INTEGER_32] external "Python" alias "mapping_mod.squares" end
	new_counter (start: INTEGER): POINTER external "Python" alias "mapping_mod.Counter" end
	bump (c: POINTER) external "Python" alias "mapping_mod.Counter.bump" end
	counter_value (c: POINTER): INTEGER external "Python" alias "mapping_mod.Counter.value" end
	nothing: detachable STRING external "Python" alias "mapping_mod.nothing" end

end
