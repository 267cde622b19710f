class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Use the aliases.
		do
			print (value.out + "%N")
			apply (2)
		end

feature -- Access

	value alias "()": INTEGER -- E: VFAV(3)
			-- No argument to put between the parentheses.
		do
			Result := 1
		end

	apply alias "()" (n: INTEGER) -- E: VFAV(3)
			-- Print `n'.
		do
			print (n.out + "%N")
		end

	twice alias "()" (n: INTEGER): INTEGER -- E: VFAV(3)
			-- A second parenthesis alias.
		do
			Result := 2 * n
		end

end
