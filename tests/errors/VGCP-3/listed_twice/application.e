class
	APPLICATION

create
	make

create {ANY}
	make -- E: VGCP(3)

feature {NONE} -- Initialization

	make
			-- Say hello.
		do
			print ("hello%N")
		end

end
