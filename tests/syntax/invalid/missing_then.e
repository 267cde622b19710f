note
	description: "An `if' whose condition is not followed by `then'."

class
	MISSING_THEN

create
	make

feature {NONE} -- Initialization

	make
			-- Print when positive.
		do
			if value > 0
				print ("positive%N") -- E: SYNTAX
			end
		end

feature -- Access

	value: INTEGER = 1

end
