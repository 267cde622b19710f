note
	description: "A customer who wants a haircut if a chair is free."

class
	CUSTOMER

create
	make

feature {NONE} -- Initialization

	make (an_id: INTEGER; a_shop: separate SHOP)
			-- Customer `an_id' going to `a_shop'.
		do
			id := an_id
			shop := a_shop
		end

feature -- Access

	id: INTEGER
			-- Customer number.

feature -- Basic operations

	visit
			-- Go to the shop and wait on a chair if one is free.
		do
			enter (shop)
		end

feature {NONE} -- Implementation

	enter (a_shop: separate SHOP)
			-- Sit down in `a_shop', or leave if it is full.
		require
			open: not a_shop.is_closed
		do
			if a_shop.has_free_chair then
				a_shop.sit_down (id)
				print ("Customer " + id.out + " sits down%N")
			else
				a_shop.turn_away
				print ("Customer " + id.out + " leaves: no free chair%N")
			end
		end

	shop: separate SHOP
			-- The shop visited.

end
