class
	SHARED_COUNTER

feature -- Access

	value: INTEGER
			-- How many times `increment' ran.

feature -- Change

	increment
			-- Add one to `value' (callers hold the mutex).
		do
			value := value + 1
		end

end
