class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			limit := 5
			classify (5)
		end

feature -- Access

	limit: INTEGER
			-- A variable, not a constant.

	zero: INTEGER = 0
			-- A constant (valid as a choice).

feature -- Output

	classify (n: INTEGER)
			-- Print a word for `n'.
		do
			inspect n
			when zero then
				print ("zero%N")
			when "one" then -- E: VOMB(2)
				print ("one%N")
			when limit then -- E: VOMB(2)
				print ("the limit%N")
			else
				print ("other%N")
			end
		end

end
