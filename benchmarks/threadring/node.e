note
	description: "A threadring node: passes a token to the next node, counting it down; the node that gets 0 wins."

class
	NODE

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_winner: separate WINNER; a_next: detachable separate NODE)
			-- Node `an_id' passing tokens to `a_next' and reporting to `a_winner' if it wins.
		do
			id := an_id
			winner := a_winner
			next := a_next
		end

feature -- Access

	id: INTEGER
			-- Node number.

feature -- Element change

	set_next (a_next: separate NODE)
			-- Pass tokens to `a_next' from now on (closing the ring).
		do
			next := a_next
		end

feature -- Basic operations

	receive (t: INTEGER)
			-- Take token `t': win if it is 0, else pass `t' - 1 on.
		do
			if t = 0 then
				finish (winner)
			else
				check ring_closed: attached next as l_next then
					pass (l_next, t - 1)
				end
			end
		end

feature {NONE} -- Implementation

	pass (n: separate NODE; t: INTEGER)
			-- Give token `t' to `n'.
		do
			n.receive (t)
		end

	finish (r: separate WINNER)
			-- Report this node as the winner to `r'.
		do
			r.set (id)
		end

	winner: separate WINNER
			-- Where the winner is recorded.

	next: detachable separate NODE
			-- The node after this one in the ring.

end
