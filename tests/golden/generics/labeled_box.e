class
	LABELED_BOX [G]

inherit
	BOX [G]

create
	make_labeled

feature {NONE} -- Initialization

	make_labeled (v: G; l: STRING)
		do
			make (v)
			label := l
		end

feature -- Access

	label: STRING
		attribute
			Result := ""
		end

end
