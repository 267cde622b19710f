note
	description: "Collects the names of a team's members."

class
	ROSTER

create
	make

feature {NONE} -- Initialization

	make
			-- Collect the names of a new team.
		local
			l_team: separate TEAM
		do
			create names.make (4)
			create l_team.make
			collect_names (l_team)
		end

feature -- Basic operations

	collect_names (a_team: separate TEAM)
			-- Append the names of the members of `a_team' to `names'.
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > a_team.members.count
			loop
				names.extend (a_team.members.i_th (i)) -- E: VUAR(2)
				names.extend (create {STRING}.make_from_separate (a_team.members.i_th (i)))
				i := i + 1
			end
			print (names.count)
		end

feature -- Access

	names: ARRAYED_LIST [STRING]
			-- Names collected so far.

end
