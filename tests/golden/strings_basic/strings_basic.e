note
	description: "STRING: mutable, 1-based, search, conversion, equality; manifest, verbatim and once strings."

class
	STRINGS_BASIC

create
	make

feature {NONE} -- Initialization

	make
		local
			s, t, u: STRING
			w: STRING_32
			parts: LIST [STRING]
			v: STRING
		do
			s := "hello"
			show ("item", s.item (1).out + s [5].out + " count " + s.count.out)
			s.put ('j', 1)
			show ("put", s)
			s [1] := 'h'
			show ("assigner", s)
			s.append (" world")
			s.append_character ('!')
			s.append_integer (42)
			show ("append", s)
			show ("substring", s.substring (2, 4) + "|" + s.substring (7, 11) + "|" + s.substring (3, 2) + "|")
			show ("index_of", s.index_of ('o', 1).out + " " + s.index_of ('o', 6).out + " " + s.index_of ('z', 1).out)
			show ("last_index_of", s.last_index_of ('l', s.count).out)
			show ("substring_index", s.substring_index ("wor", 1).out + " " + s.substring_index ("xyz", 1).out)
			show ("has", s.has ('w').out + " " + s.has_substring ("lo w").out + " " + s.occurrences ('l').out)
			show ("starts, ends", s.starts_with ("hell").out + " " + s.ends_with ("42").out)
			show ("head, tail", s.head (4) + " " + s.tail (3))
			t := "hello"
			u := "hello"
			show ("= ~ is_equal", (t = u).out + " " + (t ~ u).out + " " + t.is_equal (u).out + " " + (t = t).out)
			show ("/~", (t /~ u).out + " " + (t /~ s).out)
			u := t
			u.append ("!")
			show ("aliasing", t)
			u := t.twin
			u.append ("?")
			show ("twin", t + " " + u)
			show ("comparison", ("abc" < "abd").out + " " + ("b" > "abc").out + " " + ("ab" < "abc").out)
			show ("case", s.as_upper + " " + ("MiXeD").as_lower)
			t := "MiXeD"
			t.to_upper
			show ("to_upper", t)
			show ("mirrored", ("stressed").mirrored)
			parts := ("a,b,,c").split (',')
			show ("split count", parts.count.out)
			across parts as p loop
				print ("[" + p.item + "]")
			end
			print ("%N")
			show ("to_integer", ("42").to_integer.out + " " + ("-17").to_integer.out + " " + (("42").to_integer + 1).out)
			show ("is_integer", ("123").is_integer.out + " " + ("12a").is_integer.out + " " + ("").is_integer.out)
			show ("to_double", ("3.5").to_double.out + " " + ("2").is_double.out)
			show ("to_boolean", ("True").to_boolean.out + " " + ("false").to_boolean.out + " " + ("yes").is_boolean.out)
			t := "abcdef"
			t.remove (2)
			show ("remove", t)
			t.remove_head (1)
			t.remove_tail (1)
			show ("remove head, tail", t)
			t.prepend ("<")
			t.prepend_integer (7)
			show ("prepend", t)
			t := "  padded  "
			t.left_adjust
			show ("left_adjust", "[" + t + "]")
			t.right_adjust
			show ("right_adjust", "[" + t + "]")
			t := "a-b-c"
			t.replace_substring_all ("-", "+=")
			show ("replace_substring_all", t)
			t.keep_head (4)
			show ("keep_head", t)
			t := "ab"
			t.multiply (3)
			show ("multiply", t)
			t.wipe_out
			show ("wipe_out", t.is_empty.out + " " + t.count.out)
			show ("escapes", "quote %"q%" tab%Tpercent %% done")
			v := "[
				line one
				  line two
				]"
			print (v)
			print ("%N")
			show ("once", (tag = tag).out + " " + (fresh = fresh).out + " " + (fresh ~ fresh).out)
			tag.append ("!")
			show ("once mutated", tag + " " + tag)
			w := "wide"
			w.append_character ('r')
			show ("STRING_32", w.count.out + " " + w.as_string_8 + " " + w.out)
			show ("same_string", s.same_string ("hello world!42").out + " " + ("Abc").is_case_insensitive_equal ("aBC").out)
			show ("plus", "a" + "b" + (3).out)
			show ("out", s.out)
			print (s)
			print ("%N")
		end

feature {NONE} -- Implementation

	tag: STRING
		do
			Result := once "tag"
		end

	fresh: STRING
		do
			Result := "fresh"
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
