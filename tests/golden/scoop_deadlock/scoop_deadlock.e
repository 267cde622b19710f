note
	description: "A wait condition nobody can make true: the runtime reports the deadlock (exit 3)."

class
	SCOOP_DEADLOCK

create
	make

feature {NONE} -- Initialization

	make
		local
			box: separate MAILBOX
		do
			create box
			print ("waiting for mail%N")
			print ("got " + read (box) + "%N")
		end

feature {NONE} -- Implementation

	read (box: separate MAILBOX): STRING
		require
			mail_arrived: box.has_mail
		do
			create Result.make_from_separate (box.mail)
		end

end
