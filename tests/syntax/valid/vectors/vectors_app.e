note
	description: "Root class: bracket calls, bracket assignment and free operators on VECTOR."

class
	VECTORS_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Build two vectors and combine them.
		local
			u, v: VECTOR
			grid: ARRAY2 [INTEGER]
			table: HASH_TABLE [INTEGER, STRING]
			i: INTEGER
		do
			create u.make (3)
			create v.make (3)
			u [1] := 1.0
			u [2] := 2.0
			u.item (3) := 2.0
			v [1] := 4.0
			v [2] := u [1] + u @ 2
			print ((u |*| v).out + "%N")
			print ((# u).out + "%N")
			print ((u [1] + v [2] * 2).out + "%N")
			create grid.make_filled (0, 2, 2)
			grid [1, 2] := 12
			grid [2, 1] := grid [1, 2] + 9
			print (grid [2, 1].out + "%N")
			create table.make (10)
			table ["one"] := 1
			table ["two"] := table ["one"] + 1
			from
				i := 1
			until
				i > 3
			loop
				u [i] := u [i] * 10
				i := i + 1
			end
			print (u [3].out + " " + table ["two"].out + "%N")
		end

end
