note
	description: "[
		The grading tests of exercise 4 (README.md): three producers and two consumers, each
		on a processor of its own, share a buffer of two items.
	]"

class
	BOUNDED_BUFFER_TESTS

inherit
	EQA_TEST_SET

feature -- Tests

	test_one_producer_one_consumer
			-- Ten numbers through a buffer of two, in order.
		local
			b: separate BOUNDED_BUFFER [INTEGER]
			p: separate PRODUCER
			c: separate CONSUMER
		do
			create b.make (2)
			create p.make (b, 1, 10)
			create c.make (b, 10)
			start (p, c)
			check_in_order (c, 1, 10)
			check_buffer (b)
		end

	test_three_producers_two_consumers
			-- Thirty numbers from three producers reach two consumers, each exactly once,
			-- each producer's in order.
		local
			b: separate BOUNDED_BUFFER [INTEGER]
			p1, p2, p3: separate PRODUCER
			c1, c2: separate CONSUMER
		do
			create b.make (2)
			create p1.make (b, 100, 10)
			create p2.make (b, 200, 10)
			create p3.make (b, 300, 10)
			create c1.make (b, 12)
			create c2.make (b, 18)
			start (p1, c1)
			start (p2, c2)
			produce (p3)
			check_all (c1, c2)
			check_buffer (b)
		end

feature {NONE} -- Implementation

	start (p: separate PRODUCER; c: separate CONSUMER)
			-- Set `p' producing and `c' consuming (both asynchronously).
		do
			p.produce
			c.consume
		end

	produce (p: separate PRODUCER)
		do
			p.produce
		end

	check_in_order (c: separate CONSUMER; a_first, a_total: INTEGER)
			-- Once `c' is done: it received `a_first' ... in order.
		require
			done: c.is_done
		local
			i: INTEGER
		do
			assert_integers_equal ("count", a_total, c.received.count)
			from i := 1 until i > a_total loop
				assert_integers_equal ("number " + i.out, a_first + i - 1, c.received [i])
				i := i + 1
			end
		end

	check_all (c1, c2: separate CONSUMER)
			-- Once both are done: every number once, each producer's in order in each consumer.
		require
			done: c1.is_done and c2.is_done
		local
			seen: ARRAYED_LIST [INTEGER]
		do
			create seen.make (30)
			gather (c1, seen)
			gather (c2, seen)
			assert_integers_equal ("thirty numbers", 30, seen.count)
			assert_integers_equal ("their sum", 10 * 600 + 3 * 45, c1.sum + c2.sum)
			across 0 |..| 29 as k loop
				assert ("number " + (100 * (1 + k.item // 10) + k.item \\ 10).out + " came", seen.has (100 * (1 + k.item // 10) + k.item \\ 10))
			end
		end

	gather (c: separate CONSUMER; seen: ARRAYED_LIST [INTEGER])
			-- Add what `c' received to `seen'; check each producer's numbers came in order.
		local
			last: ARRAY [INTEGER]
			i, n: INTEGER
		do
			last := <<-1, -1, -1>>
			from i := 1 until i > c.received.count loop
				n := c.received [i]
				assert ("a producer's number: " + n.out, 100 <= n and n < 310 and n \\ 100 < 10)
				assert ("in order: " + n.out, n > last [n // 100])
				last [n // 100] := n
				seen.extend (n)
				i := i + 1
			end
		end

	check_buffer (b: separate BOUNDED_BUFFER [INTEGER])
			-- Everything was taken, and the buffer never held more than two.
		do
			assert ("empty at the end", b.is_empty)
			assert ("never more than two", b.largest_count <= 2)
		end

end
