class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER) -- E: VSRP(2)
			-- Print `n'.
		do
			print (n.out)
		end

end
