note
	description: "A from/until/loop without its `end'."

class
	MISSING_END_LOOP

create
	make

feature {NONE} -- Initialization

	make
			-- Count to ten.
		local
			i: INTEGER
		do
			from -- E: SYNTAX-END@4
				i := 1
			until
				i > 10
			loop
				print (i.out + "%N")
				i := i + 1
		end

feature -- Access

	total: INTEGER

end
