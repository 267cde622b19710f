class
	WORKER

feature

	met: BOOLEAN

	wait
		do
			met := wait_flag (20_000) = 1
		end

	signal
		do
			set_flag
		end

feature {NONE} -- Externals

	wait_flag (ms: INTEGER): INTEGER external "C blocking use %"rendezvous.h%"" alias "rendezvous_wait" end
	set_flag external "C use %"rendezvous.h%"" alias "rendezvous_set" end

end
