class
	PARENTHESIS_ALIAS

create
	make

feature {NONE} -- Initialization

	make
			-- Apply lines through their "()" alias: on an attribute, a local, a qualified call.
		local
			l: LINE
		do
			create line.make (2)
			create l.make (3)
			print (line (4).out + "%N")
			print (l (5).out + "%N")
			print (Current.line (6).out + "%N")
			l (1).do_nothing
		end

feature -- Access

	line: LINE
			-- Slope 2.

end
