class
	TALLY

feature

	value: INTEGER

	increment
		do
			value := value + 1
		end

end
