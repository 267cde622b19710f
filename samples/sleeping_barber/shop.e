note
	description: "A barber shop's waiting room with a fixed number of chairs."

class
	SHOP

create
	make

feature {NONE} -- Initialization

	make (a_chairs: INTEGER)
			-- Open shop with an empty waiting room of `a_chairs' chairs.
		require
			some_chairs: a_chairs > 0
		do
			chair_count := a_chairs
			create waiting.make (a_chairs)
		ensure
			chairs_set: chair_count = a_chairs
			empty: not has_customer
			open: not is_closed
		end

feature -- Access

	chair_count: INTEGER
			-- Chairs in the waiting room.

	arrivals: INTEGER
			-- Customers who came in.

	turned_away: INTEGER
			-- Customers who found no free chair.

	served: INTEGER
			-- Customers called to the barber's chair.

	next_customer: INTEGER
			-- The customer who has waited longest.
		require
			has_customer: has_customer
		do
			Result := waiting.item
		end

feature -- Status report

	has_free_chair: BOOLEAN
			-- Is a chair free in the waiting room?
		do
			Result := waiting.count < chair_count
		end

	has_customer: BOOLEAN
			-- Is somebody waiting?
		do
			Result := not waiting.is_empty
		end

	is_closed: BOOLEAN
			-- Has the shop closed its door?

feature -- Element change

	sit_down (a_customer: INTEGER)
			-- Let `a_customer' wait on a free chair.
		require
			open: not is_closed
			free_chair: has_free_chair
		do
			waiting.extend (a_customer)
			arrivals := arrivals + 1
		ensure
			one_more_arrival: arrivals = old arrivals + 1
			waiting: has_customer
		end

	turn_away
			-- Send away a customer who found every chair taken.
		require
			open: not is_closed
			full: not has_free_chair
		do
			turned_away := turned_away + 1
			arrivals := arrivals + 1
		end

	call_next
			-- Call the customer who has waited longest to the barber's chair.
		require
			has_customer: has_customer
		do
			waiting.remove
			served := served + 1
		ensure
			one_more_served: served = old served + 1
		end

	close
			-- Let nobody else in.
		do
			is_closed := True
		ensure
			closed: is_closed
		end

feature {NONE} -- Implementation

	waiting: ARRAYED_QUEUE [INTEGER]
			-- The waiting customers, in order of arrival.

invariant
	not_overfull: waiting.count <= chair_count
	everybody_counted: served + waiting.count + turned_away = arrivals

end
