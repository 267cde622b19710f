class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Subtract vectors.
		local
			v, w: VECTOR
		do
			create v.make (1, 2)
			create w.make (3, 4)
			v := - (v - w)
			print (v.x.out + "%N")
		end

end
