class
	SECOND

feature

	sign (x: INTEGER): INTEGER
		do
			if x > 0 then -- E: SYNTAX-END@4
				Result := 1
			elseif x < 0 then
				Result := -1
		end

feature

	zero: INTEGER = 0

end
