note
	description: "Sets both wheels of a robot to the same speed."

class
	BALANCER

create
	make

feature {NONE} -- Initialization

	make
			-- Create two wheels and balance them.
		local
			l_left, l_right: separate WHEEL
		do
			create l_left.make
			create l_right.make
			balance (l_left, l_right)
		end

feature -- Basic operations

	balance (a_left, a_right: separate WHEEL)
			-- Give `a_left' and `a_right' the same speed.
		do
			separate a_right as a_left do -- E: FRESH_IDENTIFIER
				print ("right wheel reserved%N")
			end
			a_left.set_speed (10)
			a_right.set_speed (10)
		end

end
