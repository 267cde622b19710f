note
	description: "Creation procedures that set attached attributes before reading them: directly, on %
		%every branch, or through a routine of the class they call; `Current' passed to a creation procedure %
		%that makes no qualified call; `Current' used in a qualified call once every attribute is set (VEVI)."

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
			create child.make (Current)
			create box.make ("boxed")
			show
			registry.extend (Current)
			print (child.parent.name + " " + box.item + "%N")
			print ((create {COUNT_HOLDER}.make).value)
		end

	show
			-- Print `name', set before the creation procedure calls this.
		do
			print (name + "%N")
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

	child: CHILD
			-- Made with `Current' before `box' and `registry' are set: CHILD's `make' only stores it.

	box: BOX [STRING]
			-- Holds a formal generic attribute, set by its creation procedure.

	registry: ARRAYED_LIST [ANY]
			-- Self-initializing: `Current' may be added once the other attributes are set.
		attribute
			create Result.make (1)
		end

	label: STRING
			-- Self-initializing: may be read at any time.
		attribute
			Result := "label"
		end

end
