class
	CONSUMER [G -> separate BUFFER]

feature -- Basic operations

	take (a_buffer: G)
			-- Take from `a_buffer' once it has an item: the precondition is a wait condition.
		require
			not_empty: a_buffer.count > 0
		do
			print ("took one of " + a_buffer.count.out + "%N")
		end

end
