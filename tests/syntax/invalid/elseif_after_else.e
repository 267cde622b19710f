note
	description: "An `elseif' branch after the `else' branch."

class
	ELSEIF_AFTER_ELSE

create
	make

feature {NONE} -- Initialization

	make
		local
			x: INTEGER
		do
			x := 4
			if x > 10 then
				print ("big%N")
			else
				print ("small%N")
			elseif x = 0 then -- E: SYNTAX
				print ("zero%N")
			end
		end

end
