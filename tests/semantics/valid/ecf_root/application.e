note
	description: "An .ecf names the root: an effective, non-generic class and a creation procedure %
		%other than `make`, without arguments or precondition (VSRT, VSRP)."

class
	APPLICATION

inherit
	BOX [INTEGER]

create
	start

feature {NONE} -- Initialization

	start
			-- Fill the box and print it.
		do
			put (ready_count)
			print (item.out + "%N")
		end

	ready_count: INTEGER
			-- Not a creation procedure, not the root.
		require
			True
		do
			Result := 3
		end

end
