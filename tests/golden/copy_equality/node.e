class
	NODE

inherit
	ANY
		redefine
			is_equal,
			copy
		end

create
	make

feature {NONE} -- Initialization

	make (v: INTEGER; l: STRING)
		do
			value := v
			label := l
			create children.make (2)
		end

feature -- Access

	value: INTEGER assign set_value

	label: STRING

	children: ARRAYED_LIST [NODE]

	copies: INTEGER
			-- How many times `copy' ran on this object.

feature -- Change

	set_value (v: INTEGER)
		do
			value := v
		end

	add (n: NODE)
		do
			children.extend (n)
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Same value (labels and children do not matter).
		do
			Result := value = other.value
		end

feature -- Duplication

	copy (other: like Current)
		do
			value := other.value
			label := other.label
			children := other.children
			copies := other.copies + 1
		end

end
