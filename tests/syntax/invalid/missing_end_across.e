note
	description: "An across loop without its `end'."

class
	MISSING_END_ACROSS

create
	make

feature {NONE} -- Initialization

	make
			-- Print each name.
		do
			across names as n loop -- E: SYNTAX-END@4
				print (n.item + "%N")
		end

feature -- Access

	names: ARRAY [STRING]
		once
			Result := <<"a", "b">>
		end

end
