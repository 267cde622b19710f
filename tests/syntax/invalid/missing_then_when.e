note
	description: "A `when' branch of an inspect without `then'."

class
	MISSING_THEN_WHEN

create
	make

feature {NONE} -- Initialization

	make
			-- Name the value.
		do
			inspect value
			when 1 then
				print ("one%N")
			when 2
				print ("two%N") -- E: SYNTAX
			end
		end

feature -- Access

	value: INTEGER = 2

end
