class
	HELPER

feature -- Basic operations

	work (client: separate SCOOP_CALLBACK)
			-- Call back into `client', whose processor waits for this call (lock passing).
		do
			client.record ("first")
			client.record ("second")
			print ("helper sees " + client.count.out + " entries%N")
		end

end
