class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Halve a distance until it is small.
		local
			distance: REAL_64
			i: INTEGER
		do
			from
				distance := 8.0
			until
				distance < 1.0
			loop
				distance := distance / 2
			variant
				distance -- E: VAVE
			end
			from
				i := 10
			until
				i = 0
			loop
				i := i - 1
			variant
				i
			end
		end

end
