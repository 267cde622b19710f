note
	description: "[
		SCOOP/Qs prodcons benchmark: Producer_count producers each put the values 0 to N - 1
		into one shared unbounded queue; Consumer_count consumers share the values out equally,
		each waiting while the queue is empty. N is the first argument (default 200000).
		Prints the sum of the values consumed, which must be Producer_count * N * (N - 1) / 2.
	]"

class
	PRODCONS

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
			-- Create the queue, launch the consumers then the producers, and print the sum consumed.
		local
			l_queue: separate SHARED_QUEUE
			l_consumer: separate CONSUMER
			l_producer: separate PRODUCER
			l_consumers: ARRAYED_LIST [separate CONSUMER]
			l_items: INTEGER
			l_sum: INTEGER_64
		do
			l_items := Default_items
			if argument_count >= 1 then
				l_items := argument (1).to_integer
			end
			check
				even_split: (Producer_count * l_items) \\ Consumer_count = 0
			end
			create l_queue.make
			create l_consumers.make (Consumer_count)
			across 1 |..| Consumer_count as i loop
				create l_consumer.make (l_queue, Producer_count * l_items // Consumer_count)
				l_consumers.extend (l_consumer)
			end
			across l_consumers as c loop
				launch_consumer (c.item)
			end
			across 1 |..| Producer_count as i loop
				create l_producer.make (l_queue, l_items)
				launch_producer (l_producer)
			end
			across l_consumers as c loop
				l_sum := l_sum + consumed (c.item)
			end
			print ("prodcons: producers=" + Producer_count.out + " consumers=" + Consumer_count.out + " items=" + l_items.out + " sum=" + l_sum.out + "%N")
		end

feature {NONE} -- Implementation

	launch_consumer (c: separate CONSUMER)
			-- Let `c' take its values.
		do
			c.live
		end

	launch_producer (p: separate PRODUCER)
			-- Let `p' put its values.
		do
			p.live
		end

	consumed (c: separate CONSUMER): INTEGER_64
			-- Sum of the values `c' took, once it is done (the query waits for it).
		do
			Result := c.total
		end

	Producer_count: INTEGER = 4
			-- Number of producers.

	Consumer_count: INTEGER = 4
			-- Number of consumers.

	Default_items: INTEGER = 200_000
			-- Values per producer when no argument is given.

end
