note
	description: "A conveyor belt carrying parts."

class
	CONVEYOR

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Belt with `n' parts on it.
		require
			non_negative: n >= 0
		do
			count := n
		end

feature -- Access

	count: INTEGER
			-- Parts on the belt.

feature -- Element change

	remove_part
			-- Take one part off the belt.
		require
			not_empty: count > 0
		do
			count := count - 1
		end

end
