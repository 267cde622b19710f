note
	description: "Picks up two forks."

class
	DINNER

create
	make

feature {NONE} -- Initialization

	make
			-- Create two forks and pick them up.
		do
			create left_fork.make (1)
			create right_fork.make (2)
			separate left_fork as f do
				separate right_fork as f do -- E: FRESH_IDENTIFIER
					print ("both forks reserved%N")
				end
				f.pick_up
			end
			separate left_fork as l, right_fork as r do
				l.put_down
				r.pick_up
			end
		end

feature -- Access

	left_fork: separate FORK
			-- Fork on the left.

	right_fork: separate FORK
			-- Fork on the right.

end
