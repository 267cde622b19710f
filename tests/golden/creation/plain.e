class
	PLAIN

feature -- Access

	value: INTEGER

	set_value (v: INTEGER)
		do
			value := v
		end

end
