class
	FIRST

feature

	count_down (n: INTEGER)
		local
			i: INTEGER
		do
			from
				i := n
			until
				i = 0
			loop
				print (i)
				i := i - 1
		end

end -- E: SYNTAX-END@1
