class
	REFERENCE_GENERICS

create
	make

feature {NONE} -- Initialization

	make
			-- Hold a string.
		local
			l_holder: HOLDER [STRING, INTEGER, BOOLEAN]
		do
			create l_holder
			l_holder.put ("text")
			print (l_holder.count)
		end

end
