class
	SMALL_BOX [G]

inherit
	BOX [G]

create
	make

end
