note
	description: "Iteration cursors over arrays; what `across' uses for an ARRAY."

class
	ARRAY_ITERATION_CURSOR [G]

inherit
	READABLE_INDEXABLE_ITERATION_CURSOR [G]

create
	make

end
