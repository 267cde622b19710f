note
	description: "A robot hand."

class
	HAND

create
	make

feature {NONE} -- Initialization

	make
			-- Empty hand.
		do
			is_holding := False
		end

feature -- Status report

	is_holding: BOOLEAN
			-- Does the hand hold a part?

feature -- Basic operations

	grab
			-- Take a part.
		do
			is_holding := True
		end

	release
			-- Let go of the part.
		do
			is_holding := False
		end

end
