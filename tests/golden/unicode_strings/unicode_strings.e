class
	UNICODE_STRINGS

create
	make

feature

	make
			-- Strings beyond ASCII, as EiffelStudio keeps them: a STRING_8 manifest holds the
			-- UTF-8 bytes of its text, a STRING_32 one its characters; both print the same bytes.
		local
			s: STRING
			u: STRING_32
		do
			s := "héllo ∀x 😀"
			u := "héllo ∀x 😀"
			print (s)
			print ("%N")
			print (s.count)
			print ("%N")
			print (u.count)
			print ("%N")
			print (u)
			print ("%N")
			print (u.out.count)
			print ("%N")
			print ({STRING_32} "∀")
			print ("%N")
			io.put_string ("∀%N")
			print_counts
			print_comparisons
			print_inspections
			print_utf_conversions
		end

	print_counts
			-- `count', `item' and conversions of "é" (U+00E9, UTF-8 C3 A9).
		local
			s: STRING
			u: STRING_32
		do
			s := "é"
			u := {STRING_32} "é"
			print (s.count.out + " " + u.count.out + "%N")
			print (s.item (1).code.out + " " + s.item (2).code.out + " " + u.item (1).code.out + "%N")
			s := "%/233/"
			print (s.count.out + " " + s.item (1).code.out + "%N")
			s := "%/8704/"
			print (s.count.out + "%N")
			print (s.to_string_32.count.out + " " + u.as_string_8.count.out + "%N")
			s := "aéb"
			print (s.substring (2, 3))
			print (" " + s.substring (2, 3).count.out + "%N")
		end

	print_comparisons
			-- Comparisons see the characters each string holds.
		local
			s: STRING
			u: STRING_32
		do
			s := "é"
			u := {STRING_32} "é"
			print (s.same_string_general (u))
			print (" ")
			print (s.same_string_general (u.out))
			print (" ")
			print (s ~ u.out)
			print (" ")
			print (u.same_string ({STRING_32} "é"))
			print ("%N")
		end

	print_inspections
			-- `inspect' on a string compares with the choices as the subject holds them.
		local
			s: STRING
			u: STRING_32
		do
			s := "é"
			u := {STRING_32} "é"
			inspect s
			when "é" then
				print ("STRING_8 é%N")
			else
				print ("STRING_8 other%N")
			end
			inspect u
			when "é" then
				print ("STRING_32 é%N")
			else
				print ("STRING_32 other%N")
			end
		end

	print_utf_conversions
			-- EiffelBase's UTF_CONVERTER between the bytes of a STRING_8 and the characters of a STRING_32.
		local
			u: UTF_CONVERTER
			s, bad: STRING
			w: STRING_32
		do
			s := "héllo ∀ 😀"
			w := u.utf_8_string_8_to_string_32 (s)
			print (s.count.out + " " + w.count.out + " " + w.item (2).code.out + " " + w.item (9).code.out + "%N")
			print ({UTF_CONVERTER}.string_32_to_utf_8_string_8 (w).same_string (s))
			print (" " + u.utf_8_bytes_count (w, 1, w.count).out + " ")
			create bad.make_filled ('%/233/', 1)
			print (u.is_valid_utf_8_string_8 (s).out + " " + u.is_valid_utf_8_string_8 (bad).out + "%N")
			print (w)
			print ("%N")
		end

end
