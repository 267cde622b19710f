note
	description: "Shows the first item of a store."

class
	INVENTORY_VIEW

create
	make

feature {NONE} -- Initialization

	make
			-- Create a store and show its first item.
		local
			l_store: separate STORE
		do
			create l_store.make
			show_first (l_store)
		end

feature -- Basic operations

	show_first (a_store: separate STORE)
			-- Print the first item of `a_store' and its length.
		require
			not_empty: not a_store.items.is_empty
		local
			l_item: STRING
			l_count: INTEGER
			l_separate_item: separate STRING
		do
			l_item := a_store.items.first -- E: VJAR
			l_count := a_store.items.first.count
			l_separate_item := a_store.items.first
			create l_item.make_from_separate (l_separate_item)
			print (l_item + " (" + l_count.out + ")%N")
		end

end
