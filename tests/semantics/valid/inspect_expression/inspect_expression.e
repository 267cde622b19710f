class
	INSPECT_EXPRESSION

create
	make

feature {NONE} -- Initialization

	make
			-- Name some counts with `inspect' expressions.
		local
			l_count: INTEGER
		do
			across 1 |..| 5 is k loop
				print (inspect k when 1 then "one" when 2, 3 then "few" else "many" end)
				print ("%N")
			end
			l_count := (inspect 'b' when 'a' then 1 when 'b'..'z' then 2 end) + 1
			print (l_count)
			print (name (12))
		end

	name (a_value: INTEGER): STRING
			-- A name for `a_value', with an interval choice.
		do
			Result := inspect a_value when 0 then "none" when 1..9 then "some" else "lots" end
		end

end
