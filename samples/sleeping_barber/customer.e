note
	description: "A customer who comes to the shop at a given time and waits for a haircut if a chair is free."

class
	CUSTOMER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_shop: separate SHOP; an_arrival: INTEGER_64)
			-- Customer `an_id' coming to `a_shop' `an_arrival' nanoseconds after opening.
		require
			valid_id: an_id > 0
			non_negative_arrival: an_arrival >= 0
		do
			id := an_id
			shop := a_shop
			arrival := an_arrival
		end

feature -- Access

	id: INTEGER
			-- Customer number.

	arrival: INTEGER_64
			-- When the customer comes, in nanoseconds after opening.

feature -- Basic operations

	visit
			-- Come to the shop at `arrival' time.
		do
			(create {EXECUTION_ENVIRONMENT}).sleep (arrival)
			enter (shop)
		end

feature {NONE} -- Implementation

	enter (a_shop: separate SHOP)
			-- Sit down in `a_shop' if a chair is free, or leave.
		do
			if a_shop.has_free_chair then
				a_shop.sit_down (id)
				print ("Customer " + id.out + ": sits down in the waiting room%N")
			else
				a_shop.turn_away
				print ("Customer " + id.out + ": no free chair, leaves%N")
			end
		end

	shop: separate SHOP
			-- The shop visited.

end
