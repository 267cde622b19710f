note
	description: "Creation procedures that set attached attributes before reading them: directly, on %
		%every branch, or through a routine of the class they call (VEVI)."

class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Set `name' by a routine, `title' on both branches, then read them.
		do
			set_name ("scoop")
			print (name + "%N")
			if name.count > 3 then
				title := "long"
			else
				title := "short"
			end
			print (title + " " + label + "%N")
		end

	set_name (s: STRING)
			-- Set `name' to `s'.
		do
			name := s
		end

feature -- Access

	name: STRING
			-- Set by `set_name'.

	title: STRING
			-- Set on both branches.

	label: STRING
			-- Self-initializing: may be read at any time.
		attribute
			Result := "label"
		end

end
