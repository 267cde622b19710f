class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a vector.
		local
			v: VECTOR
		do
			create v
			print (v.x)
		end

end
