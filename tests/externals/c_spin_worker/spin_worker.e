note
	description: "A worker processor inside a C external that does not return while the root waits for its result (Ctrl-C must end the program)."

class
	SPIN_WORKER

create
	make

feature

	make
		local
			s: separate SPINNER
		do
			create s
			wait_for (s)
		end

	wait_for (s: separate SPINNER)
		do
			print (s.spin.out + "%N")
		end

end
