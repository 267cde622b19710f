note
	description: "A C external called from two processors at once: one waits in C for a flag that the other sets from C."

class
	RENDEZVOUS

create
	make

feature

	make
		local
			waiter, setter: separate WORKER
		do
			create waiter
			create setter
			start (waiter, setter)
			report (waiter)
		end

	start (waiter, setter: separate WORKER)
		do
			waiter.wait
			setter.signal
		end

	report (waiter: separate WORKER)
		do
			print ("met: " + waiter.met.out + "%N")
		end

end
