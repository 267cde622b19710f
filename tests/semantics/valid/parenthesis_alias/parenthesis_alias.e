note
	description: "Calls through a %"()%" alias of a class of the program: `t (i, j)' is `t.item (i, j)'."

class
	PARENTHESIS_ALIAS

create
	make

feature {NONE} -- Initialization

	make
			-- Read a table through its alias, from an attribute, a local and a qualified call.
		local
			t: TABLE
		do
			create table.make (3)
			t := table
			print (table (1, 2) + t (2, 2) + Current.table (3, 3))
		end

feature -- Access

	table: TABLE
			-- A multiplication table.

end
