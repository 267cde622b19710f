note
	description: "ARRAY with bounds other than 1, force past both ends, resize, manifest arrays, equality."

class
	ARRAYS

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: ARRAY [INTEGER]
			names: ARRAY [STRING]
			i: INTEGER
		do
			create a.make_filled (0, -2, 2)
			a [-2] := 10
			a.put (20, 0)
			a [2] := a [-2] + a [0]
			show ("bounds", a.lower.out + " " + a.upper.out + " " + a.count.out)
			show ("items", image (a))
			a.force (99, 5)
			show ("force above", a.lower.out + " " + a.upper.out + " " + a.count.out + " " + image (a))
			a.force (7, -4)
			show ("force below", a.lower.out + " " + a.upper.out + " " + a.count.out + " " + image (a))
			a.resize (-1, 8)
			show ("resize", a.lower.out + " " + a.upper.out + " " + a.count.out)
			show ("valid_index", a.valid_index (8).out + " " + a.valid_index (9).out + " " + a.valid_index (-5).out)
			show ("has, occurrences", a.has (99).out + " " + a.has (98).out + " " + a.occurrences (0).out)
			b := <<3, 1, 4, 1, 5>>
			show ("manifest", b.lower.out + " " + b.upper.out + " " + image (b))
			show ("equality", (b ~ <<3, 1, 4, 1, 5>>).out + " " + (b = b.twin).out + " " + (b ~ b.twin).out + " " + (b ~ <<3, 1, 4>>).out)
			from
				i := b.lower
			until
				i > b.upper
			loop
				b [i] := b [i] * 10
				i := i + 1
			end
			show ("loop", image (b))
			show ("subarray", image (b.subarray (2, 4)) + " lower " + b.subarray (2, 4).lower.out)
			b.rebase (0)
			show ("rebase", b.lower.out + " " + b.upper.out + " " + b [0].out)
			create names.make_empty
			show ("empty", names.count.out + " " + names.is_empty.out + " " + names.lower.out + " " + names.upper.out)
			names.force ("first", 1)
			names.force ("second", 2)
			across names as n loop
				print (n.item + " at " + n.cursor_index.out + "%N")
			end
			create names.make_filled ("", 1, 2)
			show ("make_filled strings", (names [1] = names [2]).out)
			create a.make (1, 3)
			show ("make", image (a))
			a.fill_with (4)
			show ("fill_with", image (a))
			show ("for_all", a.for_all (agent (x: INTEGER): BOOLEAN do Result := x = 4 end).out)
		end

feature {NONE} -- Implementation

	image (a: ARRAY [INTEGER]): STRING
			-- "[i1, i2, ...]"
		do
			Result := "["
			across a is x loop
				if Result.count > 1 then
					Result.append (", ")
				end
				Result.append (x.out)
			end
			Result.append ("]")
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
