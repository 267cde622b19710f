class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			s: STRING
		do
			s := "hello"
			print (s.count)
			print (s.length) -- E: VEEN
		end

end
