class
	ONE_ERROR_PER_CLAUSE

feature -- First

	f (x: INTEGER)
		do
			if x > 0 then -- E: SYNTAX-END@4
				print (x)
		end

feature -- Second

	g: INTEGER
		do
			Result := (1 + 2
		end -- E: SYNTAX@3

	h
		do
			print ("fine")
		end

feature -- Third

	loop: INTEGER -- E: SYNTAX-RESERVED@2

end
