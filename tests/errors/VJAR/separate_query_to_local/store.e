note
	description: "A store of spare parts."

class
	STORE

create
	make

feature {NONE} -- Initialization

	make
			-- Store with two kinds of parts.
		do
			create items.make (2)
			items.extend ("wheel")
			items.extend ("bumper")
		end

feature -- Access

	items: ARRAYED_LIST [STRING]
			-- Names of the parts in stock.

end
