note
	description: "Carries out tasks that live on other processors."

class
	WORKER

create
	make

feature {NONE} -- Initialization

	make
			-- Carry out a task made on its own processor.
		local
			l_task: separate TASK
		do
			create l_task.make
			perform (l_task)
		end

feature -- Basic operations

	perform (a_task: separate TASK)
			-- Carry out `a_task' and a copy of it.
		local
			l_copy: separate TASK
		do
			a_task.carry_out
			a_task.twin.carry_out -- E: VUTA(3)
			print (a_task.twin.runs.out + "%N") -- E: VUTA(3)
			print (a_task.label.count.out + "%N")
			l_copy := a_task.twin
			perform_copy (a_task.twin)
		end

	perform_copy (a_copy: separate TASK)
			-- Carry out `a_copy'.
		do
			a_copy.carry_out
		end

end
