class
	COUNTING_LOOP

inherit
	CANCELLABLE_CONTROL_LOOP
		redefine
			step
		end

create
	make

feature

	steps: INTEGER
			-- Times `step' ran.

	first_step_at, last_step_at: REAL_64
			-- Clock readings at the first and the last step.

	step
			-- Count and time this step.
		local
			t: TIMER
		do
			create t.make
			if steps = 0 then
				first_step_at := t.now
			end
			last_step_at := t.now
			steps := steps + 1
		end

end
