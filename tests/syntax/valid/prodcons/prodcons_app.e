note
	description: "Root class: two producers and one consumer sharing a bounded buffer."

class
	PRODCONS_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Launch the processors and wait for the consumer.
		local
			buffer: separate BOUNDED_BUFFER
			p1, p2: separate PRODUCER
			c: separate CONSUMER
		do
			create buffer.make (4)
			create p1.make (buffer, 1, 10)
			create p2.make (buffer, 2, 10)
			create c.make (buffer, 20)
			launch_producer (p1)
			launch_producer (p2)
			run_consumer (c)
			separate c as sc do
				print ("total " + sc.total.out + "%N")
			end
			separate buffer as b do
				print ("left " + b.count.out + "%N")
			end
		end

feature {NONE} -- Implementation

	launch_producer (p: separate PRODUCER)
			-- Start `p' (asynchronously).
		do
			p.live
		end

	run_consumer (c: separate CONSUMER)
			-- Start `c' and wait until it has consumed everything.
		do
			c.live
			wait_until_done (c)
		end

	wait_until_done (c: separate CONSUMER)
			-- Returns when `c' has finished: a query synchronizes.
		local
			t: INTEGER
		do
			t := c.total
		end

end
