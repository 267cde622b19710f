note
	description: "SCOOP: separate creation, asynchronous commands, synchronous queries, separate blocks."

class
	SCOOP_BASIC

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: separate ACCUMULATOR
		do
			create a.make ("a")
			create b.make ("b")
			feed (a, 1, 5)
			feed (b, 10, 12)
			print ("a total " + total (a).out + "%N")
			print ("b total " + total (b).out + "%N")
			separate a as x, b as y do
				x.add (100)
				y.add (200)
				print ("in separate block: " + (x.sum + y.sum).out + "%N")
			end
			print ("name of a: " + name_of (a) + "%N")
		end

feature {NONE} -- Implementation

	feed (acc: separate ACCUMULATOR; low, high: INTEGER)
			-- Add `low' .. `high' to `acc' (asynchronously, in order).
		local
			i: INTEGER
		do
			from
				i := low
			until
				i > high
			loop
				acc.add (i)
				i := i + 1
			end
		end

	total (acc: separate ACCUMULATOR): INTEGER
		do
			Result := acc.sum
		end

	name_of (acc: separate ACCUMULATOR): STRING
		do
			create Result.make_from_separate (acc.name)
		end

end
