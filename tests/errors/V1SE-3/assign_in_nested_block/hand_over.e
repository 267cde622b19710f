note
	description: "Hands a part from one hand to the other."

class
	HAND_OVER

create
	make

feature {NONE} -- Initialization

	make
			-- Create two hands and hand a part over.
		do
			create left.make
			create right.make
			separate left as l do
				separate right as r do
					l := r -- E: V1SE(3)
					r.grab
				end
				l.release
			end
		end

feature -- Access

	left, right: separate HAND
			-- The robot's hands.

end
