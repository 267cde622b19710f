note
	description: "[
		A failed query on another processor raises EiffelStudio's dirty processor exception in
		the client (processor.c, rt_processor_execute_call: the supplier answers
		SCOOP_MESSAGE_DIRTY; private_queue.c raises it); a rescue clause catches it and a
		retry finds the region clean; uncaught, it ends the run with a report that
		names the dirty processor exception, then the supplier's failure.
	]"

class
	SCOOP_QUERY_FAILURE

create
	make

feature {NONE} -- Initialization

	make
		local
			g: separate GAUGE
		do
			create g
			print ("retried: " + read_with_retry (g).out + "%N")
			print (read (g, 5).out + "%N")
			print ("never printed%N")
		end

feature {NONE} -- Implementation

	attempts: INTEGER

	read_with_retry (g: separate GAUGE): INTEGER
			-- The level read with a limit of 0, then, after the failure, with a limit of 10.
		do
			attempts := attempts + 1
			g.set (7)
			if attempts = 1 then
				Result := g.checked_level (0)
			else
				Result := g.checked_level (10)
			end
		rescue
			print ("rescued%N")
			retry
		end

	read (g: separate GAUGE; limit: INTEGER): INTEGER
		do
			Result := g.checked_level (limit)
		end

end
