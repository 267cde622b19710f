note
	description: "[
		The sleeping barber: customers come to a shop with three chairs and leave when every
		chair is taken; the barber serves the waiting customers one at a time and sleeps
		(waits on a wait condition) while nobody is there.
	]"

class
	SLEEPING_BARBER

create
	make

feature {NONE} -- Initialization

	make
			-- Open the shop, start the barber, send the customers and close once all have come.
		local
			l_shop: separate SHOP
			l_barber: separate BARBER
			l_customer: separate CUSTOMER
			i: INTEGER
		do
			create l_shop.make (Chair_count)
			create l_barber.make (l_shop)
			start_barber (l_barber)
			from
				i := Arrivals.lower
			until
				i > Arrivals.upper
			loop
				create l_customer.make (i, l_shop, Arrivals [i].to_integer_64 * Millisecond)
				send (l_customer)
				i := i + 1
			end
			close_when_everybody_came (l_shop)
		end

feature {NONE} -- Implementation

	start_barber (a_barber: separate BARBER)
			-- Let `a_barber' work until the shop closes.
		do
			a_barber.work
		end

	send (a_customer: separate CUSTOMER)
			-- Let `a_customer' visit the shop.
		do
			a_customer.visit
		end

	close_when_everybody_came (a_shop: separate SHOP)
			-- Close `a_shop' once every customer has come by.
		require
			everybody_came: a_shop.arrivals = Arrivals.count
		do
			a_shop.close
			print ("Shop: closes after " + a_shop.arrivals.out + " customers, " + a_shop.turned_away.out + " turned away%N")
		end

	Arrivals: ARRAY [INTEGER]
			-- When each customer comes, in milliseconds after opening (a haircut takes 150).
		once
			Result := <<20, 40, 60, 80, 100, 120, 800, 820, 840, 1400>>
		end

	Chair_count: INTEGER = 3
			-- Chairs in the waiting room.

	Millisecond: INTEGER_64 = 1_000_000
			-- One millisecond, in nanoseconds.

end
