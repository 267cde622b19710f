class
	TALLY

feature -- Access

	value: INTEGER

feature -- Change

	increment
		local
			v: INTEGER
		do
			v := value
			value := v + 1
		end

end
