note
	description: "Adds a local count to a shared counter."

class
	TALLY

create
	make

feature {NONE} -- Initialization

	make
			-- Create the counter and add to it.
		do
			create counter.make
			count := 3
			separate count as c do -- E: V1SE
				print (c)
			end
			separate counter as k do
				k.add (count)
			end
		end

feature -- Access

	count: INTEGER
			-- Local count.

	counter: separate COUNTER
			-- The shared counter.

end
