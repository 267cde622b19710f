class
	UNICODE_STRINGS

create
	make

feature

	make
			-- Print strings with characters beyond Latin-1: never a NUL byte.
		local
			s: STRING
			u: STRING_32
		do
			s := "héllo ∀x 😀"
			u := "héllo ∀x 😀"
			print (s)
			print ("%N")
			print (u.count)
			print ("%N")
			print (u)
			print ("%N")
			print ({STRING_32} "∀")
			print ("%N")
			io.put_string ("∀%N")
		end

end
