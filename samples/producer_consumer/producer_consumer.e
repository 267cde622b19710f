note
	description: "Producers and consumers sharing a bounded buffer, each on its own processor."

class
	PRODUCER_CONSUMER

create
	make

feature {NONE} -- Initialization

	make
			-- Start `Producer_count' producers and as many consumers on one shared buffer,
			-- then add up what the consumers took.
		local
			buffer: separate BOUNDED_BUFFER [INTEGER]
			producer: separate PRODUCER
			consumer: separate CONSUMER
			consumers: ARRAYED_LIST [separate CONSUMER]
			total, i: INTEGER
		do
			create buffer.make (Capacity)
			create consumers.make (Producer_count)
			from
				i := 1
			until
				i > Producer_count
			loop
				create producer.make (buffer, i, Items_per_producer)
				create consumer.make (buffer, i, Items_per_producer)
				launch_producer (producer)
				launch_consumer (consumer)
				consumers.extend (consumer)
				i := i + 1
			end
			across consumers as c loop
				total := total + consumed (c.item)
			end
			print ("consumers took items adding up to " + total.out + "%N")
			check
				every_item_once: total = expected_total
			end
		end

feature {NONE} -- Implementation

	launch_producer (p: separate PRODUCER)
			-- Let `p' produce all its items.
		do
			p.live
		end

	launch_consumer (c: separate CONSUMER)
			-- Let `c' consume its share of the items.
		do
			c.live
		end

	consumed (c: separate CONSUMER): INTEGER
			-- Sum of the items `c' took, once it is done (the query waits for it).
		do
			Result := c.total
		end

	expected_total: INTEGER
			-- Sum of every item produced: producer `p' puts `p * 100 + 1' to `p * 100 + Items_per_producer'.
		local
			p: INTEGER
		do
			from
				p := 1
			until
				p > Producer_count
			loop
				Result := Result + p * 100 * Items_per_producer + Items_per_producer * (Items_per_producer + 1) // 2
				p := p + 1
			end
		end

	Capacity: INTEGER = 4
			-- Places in the shared buffer.

	Producer_count: INTEGER = 3
			-- Number of producers, and of consumers.

	Items_per_producer: INTEGER = 5
			-- Items each producer puts into the buffer.

end
