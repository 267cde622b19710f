class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Classify a speed.
		local
			speed: REAL_64
			level: INTEGER
		do
			speed := 0.5
			inspect speed -- E: VOMB(1)
			when 0 then
				print ("stopped%N")
			else
				print ("moving%N")
			end
			level := 2
			inspect level
			when 1, 2 then
				print ("slow%N")
			else
				print ("fast%N")
			end
		end

end
