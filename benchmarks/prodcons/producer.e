note
	description: "A prodcons benchmark producer: puts 0 to `items' - 1 into the shared queue."

class
	PRODUCER

create
	make

feature {NONE} -- Initialization

	make (a_queue: separate SHARED_QUEUE; an_items: INTEGER)
			-- Producer that will put `an_items' values into `a_queue'.
		do
			queue := a_queue
			items := an_items
		end

feature -- Access

	items: INTEGER
			-- Values to produce.

feature -- Basic operations

	live
			-- Put every value, each in its own reservation.
		do
			across 0 |..| (items - 1) as i loop
				put (queue, i.item)
			end
		end

feature {NONE} -- Implementation

	put (q: separate SHARED_QUEUE; v: INTEGER)
			-- Append `v' to `q'.
		do
			q.extend (v)
		end

	queue: separate SHARED_QUEUE
			-- The shared queue.

end
