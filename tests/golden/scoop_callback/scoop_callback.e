note
	description: "SCOOP lock passing: the root passes itself to a helper, which calls back while the root waits."

class
	SCOOP_CALLBACK

create
	make

feature {NONE} -- Initialization

	make
		local
			h: separate HELPER
		do
			create log.make (4)
			create h
			delegate (h)
			print ("log has " + count.out + " entries%N")
			across log is entry loop
				print (entry + "%N")
			end
		end

feature -- Callbacks

	record (s: separate STRING)
		do
			log.extend (create {STRING}.make_from_separate (s))
			print ("recorded " + log.last + "%N")
		end

	count: INTEGER
		do
			Result := log.count
		end

feature {NONE} -- Implementation

	log: ARRAYED_LIST [STRING]

	delegate (h: separate HELPER)
		do
			h.work (Current)
			print ("delegate returned%N")
		end

end
