class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print (size)
		end

feature -- Access

	size: INTEGER
			-- Number of items.

	size: INTEGER -- E: VMFN
			-- Number of items, computed.
		do
			Result := 0
		end

end
