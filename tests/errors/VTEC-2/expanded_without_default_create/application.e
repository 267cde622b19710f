class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use a size.
		local
			s: SIZE
		do
			print (s.width.out + "%N")
		end

end
