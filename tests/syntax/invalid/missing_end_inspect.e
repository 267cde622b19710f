note
	description: "An inspect instruction without its `end'."

class
	MISSING_END_INSPECT

create
	make

feature {NONE} -- Initialization

	make
			-- Name a small number.
		do
			inspect count -- E: SYNTAX-END@4
			when 1 then
				print ("one%N")
			when 2 then
				print ("two%N")
			else
				print ("many%N")
		end

feature -- Access

	count: INTEGER = 2

end
