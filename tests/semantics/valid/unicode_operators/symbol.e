class
	SYMBOL

create
	make

feature {NONE} -- Initialization

	make (a_value: INTEGER)
			-- A symbol worth `a_value'.
		do
			value := a_value
		end

feature -- Access

	value: INTEGER

	both alias "∀∀" (other: SYMBOL): BOOLEAN
			-- Are both positive?
		do
			Result := value > 0 and other.value > 0
		end

	combined alias "⊕" (other: SYMBOL): SYMBOL
			-- Sum of both.
		do
			create Result.make (value + other.value)
		end

	rotated alias "⟳": SYMBOL
			-- The opposite symbol.
		do
			create Result.make (- value)
		end

	piped alias "|>" (other: SYMBOL): INTEGER
			-- Difference.
		do
			Result := value - other.value
		end

end
