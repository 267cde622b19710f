class
	REGISTRY

feature -- Access

	shared_list: ARRAYED_LIST [STRING]
			-- One list for every REGISTRY object.
		once
			create Result.make (4)
		end

	own_list: ARRAYED_LIST [STRING]
			-- One list per REGISTRY object.
		once ("OBJECT")
			create Result.make (4)
		end

end
