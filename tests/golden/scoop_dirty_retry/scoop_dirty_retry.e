note
	description: "[
		Dirty regions as EiffelStudio's runtime has them: after a failed asynchronous call the
		supplier skips the client's logged calls, the first synchronous call is not executed and
		raises the dirty processor exception in the client, which cleans the region; a rescue
		that retries within the same reservation succeeds on its second attempt.
	]"

class
	SCOOP_DIRTY_RETRY

create
	make

feature {NONE} -- Initialization

	make
		local
			c: separate COUNTER
		do
			create c
			print ("result " + attempt (c).out + " after " + attempts.out + " attempts%N")
			print ("count after the reservation: " + count_of (c).out + "%N")
		end

feature {NONE} -- Implementation

	attempts: INTEGER

	attempt (c: separate COUNTER): INTEGER
		do
			attempts := attempts + 1
			if attempts = 1 then
				c.explode
				c.set (100)
			end
			Result := c.next
		rescue
			print ("attempt " + attempts.out + " failed%N")
			retry
		end

	count_of (c: separate COUNTER): INTEGER
		do
			Result := c.count
		end

end
