class
	SHELF [G -> {COMPARABLE, SIZED}]

feature -- Access

	item: detachable G

end
