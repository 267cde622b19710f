note
	description: "[
		Verbatim strings: aligned with [ ] and non-aligned with { },
		used here in a note clause too.
		]"

class
	VERBATIM_STRINGS

create
	make

feature {NONE} -- Initialization

	make
			-- Print verbatim strings.
		local
			s: STRING
		do
			s := "[
				This text keeps its line breaks,
				and "quotes" and %signs need no escape.
					Indentation beyond the margin stays.
				]"
			print (s + "%N")
			s := "{
				Non-aligned: the left margin
				is kept as written.
				}"
			print (s + "%N")
			s := "[
			]"
			print (s.count.out + "%N")
			s := "[
				A line with ]" inside ] brackets
				]"
			print (s + "%N")
			print (Template + "%N")
		end

feature -- Constants

	Template: STRING = "[
		<html>
			<body>$BODY</body>
		</html>
		]"
			-- A verbatim string as a constant.

end
