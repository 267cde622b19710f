class
	FIRST

feature

	count_down (n: INTEGER)
		local
			i: INTEGER
		do
			from -- E: SYNTAX-END@4
				i := n
			until
				i = 0
			loop
				print (i)
				i := i - 1
		end

end
