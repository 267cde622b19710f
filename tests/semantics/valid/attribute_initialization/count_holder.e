class
	COUNT_HOLDER

inherit
	HOLDER [INTEGER]

create
	make

feature {NONE} -- Initialization

	make
			-- Leave `value' at zero: here G is INTEGER, an expanded type that needs no setting.
		do
		end

end
