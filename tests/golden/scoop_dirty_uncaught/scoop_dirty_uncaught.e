note
	description: "[
		An uncaught dirty processor exception ends the run: the report names EiffelStudio's
		dirty processor exception, then the supplier's failure that made the region dirty.
	]"

class
	SCOOP_DIRTY_UNCAUGHT

create
	make

feature {NONE} -- Initialization

	make
		local
			c: separate COUNTER
		do
			create c
			print ("before%N")
			print (failing_then_query (c).out + "%N")
			print ("never printed%N")
		end

feature {NONE} -- Implementation

	failing_then_query (c: separate COUNTER): INTEGER
		do
			c.explode
			Result := c.next
		end

end
