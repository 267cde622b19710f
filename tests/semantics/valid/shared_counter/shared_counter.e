note
	description: "Many clients, each on its own processor, increment one counter shared by the whole program."

class
	SHARED_COUNTER

inherit
	COUNTER_ACCESS

create
	make

feature {NONE} -- Initialization

	make
			-- Start the clients and print the counter once they are all done.
		local
			l_client: separate CLIENT
		do
			across 1 |..| Client_count as i loop
				create l_client.make (i.item, Increments)
				start (l_client)
			end
			wait_for_total (counter)
			describe (counter)
		end

feature {NONE} -- Implementation

	start (a_client: separate CLIENT)
			-- Let `a_client' do its increments.
		do
			a_client.run
		end

	wait_for_total (a_counter: separate COUNTER)
			-- Print `a_counter' once every client is done.
		require
			every_increment_done: a_counter.value = Client_count * Increments
		do
			print ("Counter reached " + a_counter.value.out + "%N")
			if attached a_counter.last_caller as l_name then
				print ("Last increment by a client whose name has " + l_name.count.out + " characters%N")
			end
		end

	describe (a_thing: separate ANY)
			-- Say what `a_thing' is.
		do
			if attached {separate COUNTER} a_thing as c then
				print ("A counter at " + c.value.out + "%N")
			else
				print ("Not a counter%N")
			end
		end

	Client_count: INTEGER = 10
			-- Number of clients.

	Increments: INTEGER = 25
			-- Increments each client does.

end
