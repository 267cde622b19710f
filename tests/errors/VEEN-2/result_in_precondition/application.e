class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use `half'.
		do
			print (half (10).out + "%N")
		end

feature -- Computation

	half (n: INTEGER): INTEGER
			-- Half of `n'.
		require
			even: n \\ 2 = 0
			small: Result < 100 -- E: VEEN(2)
		do
			Result := n // 2
		ensure
			doubled: Result * 2 = n
		end

end
