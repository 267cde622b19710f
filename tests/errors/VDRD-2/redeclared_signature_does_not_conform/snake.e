class
	SNAKE

inherit
	CREATURE
		redefine
			legs, eat
		end

feature -- Access

	legs: BOOLEAN -- E: VDRD(2)
			-- Has it legs? (BOOLEAN does not conform to INTEGER.)
		do
			Result := False
		end

feature -- Basic operations

	eat (food: STRING; amount: INTEGER) -- E: VDRD(2)
			-- Swallow `amount' of `food' (one argument too many).
		do
			print ("swallowing " + food + "%N")
		end

end
