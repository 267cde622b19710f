note
	description: "SCOOP wait conditions: a producer and a consumer share a bounded buffer."

class
	SCOOP_WAIT

create
	make

feature {NONE} -- Initialization

	make
		local
			buffer: separate BUFFER
			p: separate PRODUCER
			c: separate CONSUMER
		do
			create buffer.make (2)
			create p.make (buffer, 6)
			create c.make (buffer, 6)
			start_consumer (c)
			start_producer (p)
			print ("total " + total_of (c).out + "%N")
			print ("capacity respected: " + respected (buffer).out + "%N")
		end

feature {NONE} -- Implementation

	start_producer (p: separate PRODUCER)
		do
			p.run
		end

	start_consumer (c: separate CONSUMER)
		do
			c.run
		end

	total_of (c: separate CONSUMER): INTEGER
			-- Wait until `c' has taken everything.
		require
			finished: c.is_done
		do
			Result := c.total
		end

	respected (b: separate BUFFER): BOOLEAN
		do
			Result := b.largest_count <= b.capacity and b.largest_count >= 1
		end

end
