note
	description: "A prodcons benchmark consumer: takes `count' values from the shared queue and adds them up."

class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (a_queue: separate SHARED_QUEUE; a_count: INTEGER)
			-- Consumer that will take `a_count' values out of `a_queue'.
		do
			queue := a_queue
			count := a_count
			total := 0
		end

feature -- Access

	count: INTEGER
			-- Values to take.

	total: INTEGER_64
			-- Sum of the values taken so far.

feature -- Basic operations

	live
			-- Take every value, each as soon as the queue has one.
		do
			across 1 |..| count as i loop
				take (queue)
			end
		end

feature {NONE} -- Implementation

	take (q: separate SHARED_QUEUE)
			-- Once `q' has a value, take it out and add it to `total'.
		require
			not_empty: not q.is_empty
		do
			total := total + q.item
			q.remove
		end

	queue: separate SHARED_QUEUE
			-- The shared queue.

end
