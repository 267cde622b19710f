note
	description: "[
		The order SCOOP fixes for a routine with two separate arguments (compared per processor):
		each supplier runs one client's calls in the order they were logged; a query waits for
		every call logged before it on its supplier; two arguments on one processor share one
		private queue; a reserved argument passed in a call passes the client's locks, so the
		supplier's calls on it run in the client's private queue, after what the client logged
		before and before what it logs after; an argument reserved by another processor is
		served after the client's whole reservation; a wait condition lets the routine's body
		run only once it holds.
	]"

class
	SCOOP_TWO_ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
		do
			create a.make (1)
			create b.make (2)
			create p.make (3)
			print ("two processors%N")
			both (a, b)
			print ("the same processor twice%N")
			both (a, a)
			print ("lock passing%N")
			chain (a, b)
			print ("no lock passing%N")
			relay_unreserved (a)
			show (a)
			print ("a wait condition%N")
			link (p)
			start_fill (p)
			consume (a, b)
			print ("done%N")
		end

feature {NONE} -- Implementation

	a, b, p: separate LOGGER

	both (x, y: separate LOGGER)
		do
			x.put (11)
			y.put (12)
			x.put (13)
			print ("both: logged three calls%N")
			print ("both: x has " + x.count.out + " entries%N")
			y.put (14)
			print ("both: y has " + y.count.out + " entries%N")
		end

	chain (x, y: separate LOGGER)
			-- `y' is reserved here: passing it to `x.relay' passes the locks.
		do
			y.put (20)
			x.relay (y, 21)
			print ("chain: relay returned%N")
			y.put (22)
		end

	relay_unreserved (x: separate LOGGER)
			-- `b' is not reserved here: `x' reserves it itself, after this routine.
		do
			x.relay (b, 23)
			print ("relay_unreserved: logged%N")
		end

	show (x: separate LOGGER)
		do
			print ("show: x has " + x.count.out + " entries%N")
		end

	link (q: separate LOGGER)
		do
			q.set_peer (b)
		end

	start_fill (q: separate LOGGER)
		do
			q.fill (3)
		end

	consume (x, y: separate LOGGER)
		require
			filled: y.count >= 9
		do
			x.put (31)
			y.put (32)
			print ("consume: y has " + y.count.out + " entries%N")
		end

end
