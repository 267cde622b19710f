class
	SMALL_BOX

inherit
	BOX

create
	make

end
