class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Compare a count with some values.
		local
			count: INTEGER
			ratio: REAL_64
			answer: STRING
			done: BOOLEAN
		do
			count := 3
			answer := "3"
			if count = answer then -- E: VWEQ
				print ("same%N")
			end
			if done = count then -- E: VWEQ
				print ("odd%N")
			end
			ratio := count
			if ratio = count and count /= 0 and count.out ~ answer then
				print ("fine%N")
			end
		end

end
