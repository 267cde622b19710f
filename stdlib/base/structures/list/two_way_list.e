note
	description: "[
		Lists made of cells linked in both directions. Every LINKED_LIST of this
		library is already linked both ways, so this class adds no feature; it exists
		for programs that name it.
	]"

class
	TWO_WAY_LIST [G]

inherit
	LINKED_LIST [G]

create
	make,
	make_from_iterable

end
