class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Run the example.
		do
			print (shared_count)
		end

feature -- Access

	shared_count: INTEGER
			-- Computed once.
		once ("PROGRAM") -- E: ONCE-KEY
			Result := 42
		end

end
