note
	description: "The barber, who serves customers while there are any and sleeps otherwise."

class
	BARBER

create
	make

feature {NONE} -- Initialization

	make (a_shop: separate SHOP)
			-- Barber working in `a_shop'.
		do
			shop := a_shop
		end

feature -- Access

	haircuts: INTEGER
			-- Haircuts given so far.

feature -- Basic operations

	work
			-- Serve customers until the shop is closed and empty.
		do
			from
			until
				is_done
			loop
				serve_next (shop)
			end
			print ("Barber gave " + haircuts.out + " haircuts%N")
		end

feature {NONE} -- Implementation

	serve_next (a_shop: separate SHOP)
			-- Serve the next customer of `a_shop'; sleep while there is none.
		require
			customer_or_closed: a_shop.has_customer or a_shop.is_closed
		do
			if a_shop.has_customer then
				cut_hair (a_shop.next_customer)
				a_shop.call_next
			else
				is_done := True
			end
		end

	cut_hair (a_customer: INTEGER)
			-- Give `a_customer' a haircut.
		do
			haircuts := haircuts + 1
			print ("Barber cuts the hair of customer " + a_customer.out + "%N")
		end

	shop: separate SHOP
			-- Where the barber works.

	is_done: BOOLEAN
			-- Has the shop closed with nobody left waiting?

end
