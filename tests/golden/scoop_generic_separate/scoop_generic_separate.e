note
	description: "[
		A call whose target's type is a formal generic with a separate constraint and a separate
		actual: the routine reserves that argument, as EiffelStudio does (it failed with a false
		`not reserved' run-time error).
	]"

class
	SCOOP_GENERIC_SEPARATE

create
	make

feature {NONE} -- Initialization

	make
		local
			r: RUNNER [separate WORKABLE]
			w, v: separate WORKABLE
			all_workers: ARRAYED_LIST [separate WORKABLE]
		do
			create w
			create v
			create r
			r.run (w, 3)
			r.run (w, 4)
			print ("total of w: " + r.total (w).out + "%N")
			create all_workers.make (2)
			all_workers.extend (w)
			all_workers.extend (v)
			r.run_all (all_workers, 10)
			print ("totals: " + r.total (w).out + " " + r.total (v).out + "%N")
		end

end
