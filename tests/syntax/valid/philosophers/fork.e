note
	description: "Forks: each lives on its own processor and is reserved by a philosopher."

class
	FORK

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Fork number `n'.
		do
			id := n
		end

feature -- Access

	id: INTEGER
	uses: INTEGER

feature -- Basic operations

	use
			-- Record one more use.
		do
			uses := uses + 1
		end

end
