class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Reserve a local list that is not separate.
		local
			l_items: ARRAYED_LIST [INTEGER]
			l_shared: separate ARRAYED_LIST [INTEGER]
		do
			create l_items.make (1)
			create l_shared.make (1)
			separate l_items as x do -- E: V1SE
				x.extend (1)
			end
			separate l_shared as y do
				y.extend (2)
			end
		end

end
