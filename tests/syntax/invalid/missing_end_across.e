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
			across names as n loop
				print (n.item + "%N")
		end

feature -- Access -- E: SYNTAX-END

	names: ARRAY [STRING]
		once
			Result := <<"a", "b">>
		end

end
