note
	description: "`loop' is a keyword and cannot name a local variable."

class
	RESERVED_LOOP_LOCAL

create
	make

feature {NONE} -- Initialization

	make
			-- Count laps.
		local
			loop: INTEGER -- E: SYNTAX-RESERVED
		do
			print ("laps%N")
		end

end
