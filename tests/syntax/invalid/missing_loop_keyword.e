note
	description: "A from/until loop whose body is not introduced by `loop'."

class
	MISSING_LOOP_KEYWORD

create
	make

feature {NONE} -- Initialization

	make
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > 3
				i := i + 1 -- E: SYNTAX
			end
		end

end
