class
	FRAGILE

feature -- Change

	explode
		do
			check
				never: False
			end
		end

end
