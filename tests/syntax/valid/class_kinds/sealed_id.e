note
	description: "A frozen class: no class may inherit from it."

frozen class
	SEALED_ID

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Identifier `n'.
		do
			value := n
		end

feature -- Access

	value: INTEGER
			-- The identifier.

	frozen as_text: STRING
			-- `value' as text.
		do
			Result := "#" + value.out
		end

end
