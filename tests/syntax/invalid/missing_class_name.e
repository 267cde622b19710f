note
	description: "The class header has no name."

class

create -- E: SYNTAX
	make

feature {NONE} -- Initialization

	make
		do
		end

end
