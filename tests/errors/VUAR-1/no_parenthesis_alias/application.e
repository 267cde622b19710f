class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Apply `line' to an argument: LINE has no "()" alias.
		do
			create line.make (2)
			print (line (4)) -- E: VUAR(1)
		end

feature -- Access

	line: LINE
			-- A linear function.

end
