note
	description: "[
		The sleeping barber: customers arrive at a shop with a few chairs and leave when
		every chair is taken; the barber serves the waiting customers one at a time and
		waits (sleeps) while nobody is there.
	]"

class
	SLEEPING_BARBER

create
	make

feature {NONE} -- Initialization

	make
			-- Open the shop, start the barber and send the customers.
		local
			l_shop: separate SHOP
			l_barber: separate BARBER
			l_customer: separate CUSTOMER
			i: INTEGER
		do
				-- The shop has no processor of its own: whoever uses it runs its features.
			create <NONE> l_shop.make (Chair_count)
			create l_barber.make (l_shop)
			start_barber (l_barber)
			from
				i := 1
			until
				i > Customer_count
			loop
				create l_customer.make (i, l_shop)
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
			everybody_came: a_shop.arrivals = Customer_count
		do
			a_shop.close
			print ("Shop closed: " + a_shop.turned_away.out + " customers were turned away%N")
		end

	Chair_count: INTEGER = 3
			-- Chairs in the waiting room.

	Customer_count: INTEGER = 8
			-- Customers coming to the shop.

end
