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
			inspect count
			when 1 then
				print ("one%N")
			when 2 then
				print ("two%N")
			else
				print ("many%N")
		end

feature -- Access -- E: SYNTAX-END

	count: INTEGER = 2

end
