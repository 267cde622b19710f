note
	description: "[
		The pattern of EiffelStudio's partree example (Src/examples/scoop/partree): the root
		processor holds the data, asks a leaf on another processor to compute over it, then waits
		for the leaf's result; the leaf must reserve the root's processor to read the data, and the
		root serves no one until its own routine ends. A deadlock under SCOOP's rules, as in
		EiffelStudio (which hangs); scoopc reports it.
	]"

class
	TREE_DEADLOCK

create
	make

feature {NONE} -- Initialization

	make
			-- Give a leaf data that lives on this processor, then wait for its result.
		local
			data: SPECIAL [INTEGER]
			leaf: separate LEAF
		do
			create data.make_filled (1, 3)
			create leaf.make (data)
			run (leaf)
		end

	run (a_leaf: separate LEAF)
			-- Let `a_leaf' compute, then wait for its total.
		do
			a_leaf.compute
			print (a_leaf.total)
		end

end
