class
	JOB

create
	make

feature

	make (q: separate JOB_QUEUE; n: INTEGER)
			-- Register an agent of this passive region with `q`.
		do
			q.add (agent (k: INTEGER) do print ("job " + k.out + "%N") end (n))
		end

end
