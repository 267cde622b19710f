class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			box: BOX
		do
			create box
			box [2] := 5 -- E: VBAC(2)
			print (box [2])
		end

end
