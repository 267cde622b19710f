class
	MOVER

feature

	move (from: INTEGER) -- E: SYNTAX-RESERVED@8
		do
			print (from)
		end

end
