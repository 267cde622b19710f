class
	DEVICE

inherit
	READER
	WRITER

create
	make

feature {NONE} -- Initialization

	make
			-- Set up both sides.
		do
		end

end
