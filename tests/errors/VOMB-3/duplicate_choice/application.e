class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			classify (4)
		end

feature -- Output

	classify (n: INTEGER)
			-- Print a word for `n'.
		do
			inspect n
			when 1 then
				print ("one%N")
			when 2, 1 then -- E: VOMB(3)
				print ("two%N")
			when 3 .. 5 then
				print ("a few%N")
			when 4 then -- E: VOMB(3)
				print ("four%N")
			else
				print ("many%N")
			end
		end

end
