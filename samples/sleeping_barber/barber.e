note
	description: "The barber: cuts the hair of the waiting customers one at a time, and sleeps while there is none."

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
			-- Serve customers until the shop is closed and nobody is left waiting.
		do
			from
			until
				is_done
			loop
				nap_if_idle (shop)
				call_customer (shop)
				if customer /= 0 then
					cut_hair
				end
			end
			print ("Barber: shop closed, " + haircuts.out + " haircuts given%N")
		end

feature {NONE} -- Implementation

	nap_if_idle (a_shop: separate SHOP)
			-- Fall asleep in the barber's chair if nobody is waiting.
		do
			if not a_shop.has_customer and not a_shop.is_closed then
				print ("Barber: nobody waiting, falls asleep%N")
			end
		end

	call_customer (a_shop: separate SHOP)
			-- Sleep until a customer is waiting or the shop is closed, then call the next customer.
		require
			customer_or_closed: a_shop.has_customer or a_shop.is_closed
		do
			if a_shop.has_customer then
				customer := a_shop.next_customer
				a_shop.call_next
			else
				customer := 0
				is_done := True
			end
		ensure
			done_when_closed_and_empty: is_done = (customer = 0)
		end

	cut_hair
			-- Give the current customer a haircut, which takes a while.
		require
			has_customer: customer /= 0
		do
			print ("Barber: cuts the hair of customer " + customer.out + "%N")
			(create {EXECUTION_ENVIRONMENT}).sleep (Haircut_time)
			haircuts := haircuts + 1
		ensure
			one_more_haircut: haircuts = old haircuts + 1
		end

	shop: separate SHOP
			-- Where the barber works.

	customer: INTEGER
			-- Customer in the barber's chair, 0 if none.

	is_done: BOOLEAN
			-- Has the shop closed with nobody left waiting?

	Haircut_time: INTEGER_64 = 150_000_000
			-- Time a haircut takes, in nanoseconds.

end
