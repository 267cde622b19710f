note
	description: "An attribute declared without the colon before its type."

class
	MISSING_COLON

create
	make

feature {NONE} -- Initialization

	make
		do
			count := 1
		end

feature -- Access

	count INTEGER -- E: SYNTAX

end
