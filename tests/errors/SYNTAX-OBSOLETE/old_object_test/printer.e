class
	PRINTER

feature

	show (a: ANY)
		do
			if {s: STRING} a then -- E: SYNTAX-OBSOLETE@9
				print (s)
			end
		end

end
