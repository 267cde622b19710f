class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		local
			c0: CELSIUS_NOT_FOUND
			c1: CELSIUS_NOT_A_CREATION_PROCEDURE
			c2: CELSIUS_NOT_ONE_ARGUMENT
			c3: CELSIUS_SOURCE_NOT_CONFORMING
			c4: CELSIUS_NOT_A_QUERY
			c5: CELSIUS_TYPE_TWICE
			c6: CELSIUS_ROUTINE_TWICE
			c7: CELSIUS_RESULT_NOT_CONFORMING
		do
			c0 := 21
			print (c0.degrees)
			c1 := 21
			print (c1.degrees)
			c2 := 21
			print (c2.degrees)
			c3 := 21
			print (c3.degrees)
			c4 := 21
			print (c4.degrees)
			c5 := 21
			print (c5.degrees)
			c6 := 21
			print (c6.degrees)
			c7 := 21
			print (c7.degrees)
		end

end
