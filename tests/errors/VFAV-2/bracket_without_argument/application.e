class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Read a register.
		local
			r: REGISTER
		do
			create r.make
			print (r.value.out + "%N")
		end

end
