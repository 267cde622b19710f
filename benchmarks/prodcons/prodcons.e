note
	description: "[
		SCOOP/Qs prodcons benchmark: Producer_count producers each put the values 0 to N - 1
		into one shared unbounded queue; Consumer_count consumers share the values out equally,
		each waiting while the queue is empty. N is the first argument (default 200000),
		Producer_count the second (default 4), Consumer_count the third (default 4).
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
			producer_count := Default_producers
			if argument_count >= 2 then
				producer_count := argument (2).to_integer
			end
			consumer_count := Default_consumers
			if argument_count >= 3 then
				consumer_count := argument (3).to_integer
			end
			check
				even_split: (producer_count * l_items) \\ consumer_count = 0
			end
			create l_queue.make
			create l_consumers.make (consumer_count)
			across 1 |..| consumer_count as i loop
				create l_consumer.make (l_queue, producer_count * l_items // consumer_count)
				l_consumers.extend (l_consumer)
			end
			across l_consumers as c loop
				launch_consumer (c.item)
			end
			across 1 |..| producer_count as i loop
				create l_producer.make (l_queue, l_items)
				launch_producer (l_producer)
			end
			across l_consumers as c loop
				l_sum := l_sum + consumed (c.item)
			end
			print ("prodcons: producers=" + producer_count.out + " consumers=" + consumer_count.out + " items=" + l_items.out + " sum=" + l_sum.out + "%N")
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

	producer_count: INTEGER
			-- Number of producers.

	consumer_count: INTEGER
			-- Number of consumers.

	Default_producers: INTEGER = 4
			-- Number of producers when no second argument is given.

	Default_consumers: INTEGER = 4
			-- Number of consumers when no third argument is given.

	Default_items: INTEGER = 200_000
			-- Values per producer when no argument is given.

end
