note
	description: "Producers and consumers sharing a bounded buffer, each on its own processor."

class
	PRODUCER_CONSUMER

create
	make

feature {NONE} -- Initialization

	make
			-- Start `Producer_count' producers and as many consumers on one shared buffer.
		local
			buffer: separate BOUNDED_BUFFER [INTEGER]
			producer: separate PRODUCER
			consumer: separate CONSUMER
			i: INTEGER
		do
			create buffer.make (Capacity)
			from
				i := 1
			until
				i > Producer_count
			loop
				create producer.make (buffer, i, Items_per_producer)
				create consumer.make (buffer, i, Items_per_producer)
				launch_producer (producer)
				launch_consumer (consumer)
				i := i + 1
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

	Capacity: INTEGER = 4
			-- Places in the shared buffer.

	Producer_count: INTEGER = 3
			-- Number of producers, and of consumers.

	Items_per_producer: INTEGER = 5
			-- Items each producer puts into the buffer.

end
