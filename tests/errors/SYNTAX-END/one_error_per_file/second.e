class
	SECOND

feature

	sign (x: INTEGER): INTEGER
		do
			if x > 0 then
				Result := 1
			elseif x < 0 then
				Result := -1
		end

feature -- E: SYNTAX-END@1

	zero: INTEGER = 0

end
