class
	UNICODE_OPERATORS

create
	make

feature {NONE} -- Initialization

	make
			-- Use free operators written with Unicode symbols.
		local
			a, b: SYMBOL
		do
			create a.make (2)
			create b.make (3)
			print (a ∀∀ b)
			print ((a ⊕ b).value)
			print (a.rotated.value)
			print (a |> b)
		end

end
