note
	description: "A team of robot operators."

class
	TEAM

create
	make

feature {NONE} -- Initialization

	make
			-- A team of three.
		do
			create members.make (3)
			members.extend ("Ada")
			members.extend ("Grace")
			members.extend ("Niklaus")
		end

feature -- Access

	members: ARRAYED_LIST [STRING]
			-- Names of the members.

end
