class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print ("trying%N")
			attempts := attempts + 1
			if attempts < 3 then
				retry -- E: VXRT
			end
		end

feature -- Access

	attempts: INTEGER
			-- Number of attempts so far.

end
