note
	description: "Checks two forks at once."

class
	PAIR_CHECK

create
	make

feature {NONE} -- Initialization

	make
			-- Create two forks and check them together.
		local
			l_first, l_second: separate FORK
		do
			create l_first.make (1)
			create l_second.make (2)
			separate l_first as f, l_second as f do -- E: FRESH_IDENTIFIER
				print ("forks reserved%N")
			end
			separate l_first as f1, l_second as f2 do
				if f1.is_in_use or f2.is_in_use then
					print ("busy%N")
				end
			end
		end

end
