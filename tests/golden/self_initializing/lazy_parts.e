class
	LAZY_PARTS

create
	make, make_named

feature {NONE} -- Initialization

	make
		do
		end

	make_named (n: STRING)
		do
			name := n
		end

feature -- Access

	name: STRING
			-- Computed by its body when read while still Void.
		attribute
			print ("(body of name runs) ")
			Result := "computed"
		end

	parts: ARRAYED_LIST [INTEGER]
		attribute
			print ("(body of parts runs) ")
			create Result.make (2)
		end

	count: INTEGER
			-- Expanded: never Void, so its body never runs.
		attribute
			print ("(body of count runs) ")
			Result := 42
		end

	label: detachable STRING
			-- Detachable: Void is a value, the body never runs.
		attribute
			print ("(body of label runs) ")
			Result := "label"
		end

end
