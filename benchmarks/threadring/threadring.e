note
	description: "[
		SCOOP/Qs threadring benchmark (from the benchmarks game): Node_count nodes in a ring,
		each its own processor; node 1 gets the token N, each node passes the token minus one
		to the next, and the node that gets 0 wins. N is the first argument (default 300000),
		Node_count the second (default 503). Prints the winner, which must be
		N \\ Node_count + 1.
	]"

class
	THREADRING

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Build the ring, start the token, print the winner.
		local
			l_winner: separate WINNER
			l_last, l_next: separate NODE
			l_hops, i: INTEGER
		do
			l_hops := Default_hops
			if argument_count >= 1 then
				l_hops := argument (1).to_integer
			end
			node_count := Default_nodes
			if argument_count >= 2 then
				node_count := argument (2).to_integer
			end
			create l_winner.make
			create l_last.make (node_count, l_winner, Void)
			from
				l_next := l_last
				i := node_count - 1
			until
				i = 0
			loop
				create l_next.make (i, l_winner, l_next)
				i := i - 1
			end
			first := l_next
			close_ring (l_last)
			start (first, l_hops)
			report (l_winner, l_hops)
		end

feature {NONE} -- Implementation

	first: separate NODE
			-- Node 1, which gets the token first.

	close_ring (a_last: separate NODE)
			-- Let `a_last' pass tokens to `first'.
		do
			a_last.set_next (first)
		end

	start (a_first: separate NODE; a_hops: INTEGER)
			-- Give the token `a_hops' to `a_first'.
		do
			a_first.receive (a_hops)
		end

	report (r: separate WINNER; a_hops: INTEGER)
			-- Once the winner is known, print it.
		require
			known: r.is_set
		do
			print ("threadring: nodes=" + node_count.out + " hops=" + a_hops.out + " winner=" + r.id.out + "%N")
		end

	node_count: INTEGER
			-- Nodes in the ring.

	Default_nodes: INTEGER = 503
			-- Nodes in the ring when no second argument is given.

	Default_hops: INTEGER = 300_000
			-- Token passes when no argument is given.

end
