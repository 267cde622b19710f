class
	FLAG

feature

	is_set: BOOLEAN

	set
		do
			is_set := True
		end

end
