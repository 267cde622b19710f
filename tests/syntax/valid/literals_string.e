note
	description: "Manifest strings with %% escapes, codes and multi-line continuation."

class
	LITERALS_STRING

create
	make

feature {NONE} -- Initialization

	make
			-- Print strings written in several ways.
		local
			s: STRING
		do
			s := "plain"
			print (s + "%N")
			s := ""
			print (s.count.out + "%N")
			s := "tab:%Tend, quote: %", percent: %%, apostrophe: %'"
			print (s + "%N")
			s := "codes: %/65/%/66/%/67/"
			print (s + "%N")
			s := "specials: %A%B%C%D%F%H%L%Q%S%V%(%)%<%>%U%R"
			print (s.count.out + "%N")
			s := "a -- not a comment"
			print (s + "%N")
			s := "single 'quotes' inside"
			print (s + "%N")
			s := "A long string that is continued %
				%on the next line and %
				%on a third one."
			print (s + "%N")
			s := "line one%Nline two%N"
			print (s)
			print (("abc").count.out + "%N")
			print (("x" + "y").twin + "%N")
			print ({STRING_32} "typed" + "%N")
			print ({STRING_8} "typed 8")
			print ("%N")
		end

end
