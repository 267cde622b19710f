note
	description: "With --strict, an exception lost in an asynchronous call is a run-time failure (exit 3)."

class
	SCOOP_LOST_STRICT

create
	make

feature {NONE} -- Initialization

	make
		local
			f: separate FRAGILE
		do
			create f
			print ("before the lost exception%N")
			fire_and_forget (f)
		end

feature {NONE} -- Implementation

	fire_and_forget (f: separate FRAGILE)
		do
			f.explode
		end

end
