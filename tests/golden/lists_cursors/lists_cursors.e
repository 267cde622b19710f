note
	description: "ARRAYED_LIST and LINKED_LIST through their cursors: start, forth, after, item, search, remove."

class
	LISTS_CURSORS

create
	make

feature {NONE} -- Initialization

	make
		local
			a: ARRAYED_LIST [INTEGER]
			k: LINKED_LIST [INTEGER]
			words: LINKED_LIST [STRING]
		do
			create a.make (2)
			print ("ARRAYED_LIST%N")
			exercise (a)
			create k.make
			print ("LINKED_LIST%N")
			exercise (k)
			create words.make
			words.extend ("alpha")
			words.extend ("beta")
			show ("has by reference", words.has ("beta").out)
			words.compare_objects
			show ("has by object", words.has ("beta").out)
			words.start
			words.search ("beta")
			show ("search string", words.index.out + " " + words.item)
		end

feature {NONE} -- Implementation

	exercise (l: DYNAMIC_LIST [INTEGER])
			-- The same operations on any list.
		local
			c: CURSOR
		do
			show ("empty", l.is_empty.out + " " + l.count.out + " before " + l.before.out + " index " + l.index.out)
			across 1 |..| 6 is i loop
				l.extend (i * 10)
			end
			show ("extended", image (l) + " index " + l.index.out)
			from
				l.start
			until
				l.after
			loop
				print (l.item.out + "@" + l.index.out + " ")
				l.forth
			end
			print ("%N")
			show ("after", l.after.out + " index " + l.index.out + " off " + l.off.out)
			l.start
			l.search (40)
			show ("search 40", l.index.out + " " + l.item.out)
			l.search (20)
			show ("search 20 from there", l.after.out + " " + l.exhausted.out)
			show ("first, last, i_th", l.first.out + " " + l.last.out + " " + l.i_th (2).out + " " + l [3].out)
			l.go_i_th (2)
			c := l.cursor
			l.finish
			show ("finish", l.index.out + " " + l.islast.out)
			l.back
			show ("back", l.item.out)
			l.go_to (c)
			show ("go_to", l.index.out + " " + l.item.out + " " + l.isfirst.out)
			l.put_left (15)
			l.put_right (25)
			show ("put_left, put_right", image (l) + " index " + l.index.out + " item " + l.item.out)
			l.replace (21)
			l.put_front (5)
			show ("replace, put_front", image (l) + " index " + l.index.out)
			l [1] := 1
			show ("assigner", image (l))
			l.start
			l.remove
			show ("remove first", image (l) + " index " + l.index.out + " item " + l.item.out)
			from
				l.start
			until
				l.after
			loop
				if l.item \\ 20 = 0 then
					l.remove
				else
					l.forth
				end
			end
			show ("multiples of 20 removed", image (l) + " count " + l.count.out)
			l.finish
			l.remove
			show ("remove last", image (l) + " after " + l.after.out)
			show ("index_of", l.index_of (25, 1).out + " " + l.index_of (99, 1).out)
			show ("occurrences", l.occurrences (15).out)
			show ("for_all", l.for_all (agent (x: INTEGER): BOOLEAN do Result := x > 10 end).out)
			show ("there_exists", l.there_exists (agent (x: INTEGER): BOOLEAN do Result := x = 30 end).out)
			l.do_all (agent (x: INTEGER) do print (x.out + ";") end)
			print ("%N")
			l.wipe_out
			show ("wipe_out", l.count.out + " " + l.is_empty.out)
		end

	image (l: LIST [INTEGER]): STRING
		do
			Result := ""
			across l as c loop
				if not Result.is_empty then
					Result.append (",")
				end
				Result.append (c.item.out)
			end
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
