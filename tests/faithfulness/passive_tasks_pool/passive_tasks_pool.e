class
	PASSIVE_TASKS_POOL

create
	make

feature

	make
			-- Jobs made in passive regions are run by two workers that share a queue.
		local
			j: separate JOB
		do
			create queue.make (2)
			across 1 |..| 6 as i loop
				create <NONE> j.make (queue, i.item)
			end
			close (queue)
		end

	queue: separate JOB_QUEUE

	close (q: separate JOB_QUEUE)
		do
			q.close
		end

end
