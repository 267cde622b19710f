class CELL

feature

	value: INTEGER

	set (v: INTEGER)
		do
			value := v
		end

end
