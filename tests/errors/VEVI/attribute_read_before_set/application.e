class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make (flag: BOOLEAN)
			-- Read `name' and `title' too early.
		do
			print (name.count.out + "%N") -- E: VEVI
			name := "scoop"
			if flag then
				title := "on"
			end
			print (title + name + "%N") -- E: VEVI
			title := "off"
		end

feature -- Access

	name: STRING
			-- Set second.

	title: STRING
			-- Set on one branch only.

end
