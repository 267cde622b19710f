note
	description: "Sets up arms on an assembly line."

class
	ASSEMBLY_LINE

create
	make

feature {NONE} -- Initialization

	make
			-- Create three arms and operate them.
		local
			l_arm: separate ARM
		do
			create <ARM> l_arm.make -- E: SYNTAX
			operate (create <ROBOT> {separate ARM}.make) -- E: SYNTAX
			operate (create <NONE> {separate ARM}.make)
			operate (l_arm)
		end

feature -- Basic operations

	operate (a_arm: separate ARM)
			-- Move `a_arm' once.
		do
			a_arm.move
		end

end
