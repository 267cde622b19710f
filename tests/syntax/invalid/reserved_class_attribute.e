note
	description: "`class' is a keyword and cannot name an attribute."

class
	RESERVED_CLASS_ATTRIBUTE

create
	make

feature {NONE} -- Initialization

	make
		do
			print ("student%N")
		end

feature -- Access

	class: STRING -- E: SYNTAX-RESERVED
			-- The student's class.

end
