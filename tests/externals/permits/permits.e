note
	description: "[
		Blocking and non-blocking externals: a `Python blocking' (or `C blocking') external gives up
		its processor's run permit while it runs, one not marked blocking keeps it (EiffelStudio
		runs a blocking external outside Eiffel mode, EIF_ENTER_C). The same Python function,
		bound twice, says whether the processor running it holds its permit, on the root's
		processor and on a worker's.
	]"

class
	PERMITS

create
	make, make_worker

feature

	make
		local
			worker: separate PERMITS
		do
			print ("root: blocking " + held_blocking.out + ", not blocking " + held.out + "%N")
			create worker.make_worker
			report (worker)
		end

	make_worker
		do
		end

	report (a_worker: separate PERMITS)
		do
			print ("worker: blocking " + a_worker.held_blocking.out + ", not blocking " + a_worker.held.out + "%N")
		end

feature -- Externals

	held_blocking: BOOLEAN
			-- Does the processor running this external hold its run permit meanwhile?
		external "Python blocking" alias "permits_mod.holds_permit" end

	held: BOOLEAN
			-- The same, not blocking.
		external "Python" alias "permits_mod.holds_permit" end

end
