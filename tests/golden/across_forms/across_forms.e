note
	description: "across: loop, all and some; `as' (cursor) and `is' (item) forms; intervals, lists, tables, strings."

class
	ACROSS_FORMS

create
	make

feature {NONE} -- Initialization

	make
		local
			list: LINKED_LIST [INTEGER]
			table: HASH_TABLE [STRING, STRING]
			sum: INTEGER
			a: ARRAY [STRING]
		do
			across 1 |..| 5 as i loop
				print (i.item.out + " ")
			end
			print ("%N")
			across 1 |..| 5 is i loop
				sum := sum + i
			end
			print ("sum " + sum.out + "%N")
			across 5 |..| 1 is i loop
				print ("never " + i.out)
			end
			across -2 |..| 2 as i loop
				print (i.item.out + (if i.is_last then "%N" else "," end))
			end
			create list.make
			across <<4, 8, 15, 16, 23, 42>> is x loop
				list.extend (x)
			end
			list.start
			across list as c loop
				print (c.item.out + "@" + c.cursor_index.out + " ")
			end
			print ("%N")
			print ("list cursor untouched: " + list.index.out + "%N")
			print ("all positive: " + (across list is x all x > 0 end).out + "%N")
			print ("all even: " + (across list is x all x \\ 2 = 0 end).out + "%N")
			print ("some above 40: " + (across list as c some c.item > 40 end).out + "%N")
			print ("some square is 49: " + (across 1 |..| 10 as i some i.item * i.item = 49 end).out + "%N")
			print ("all over empty: " + (across 3 |..| 2 is i all i > 100 end).out + "%N")
			print ("some over empty: " + (across 3 |..| 2 is i some i > 0 end).out + "%N")
			across list as c until c.item > 15 loop
				print (c.item.out + " ")
			end
			print ("%N")
			create table.make (3)
			table.put ("uno", "one")
			table.put ("dos", "two")
			table.put ("tres", "three")
			across table as t loop
				print (t.key + "->" + t.item + " ")
			end
			print ("%N")
			across table is w loop
				print (w + " ")
			end
			print ("%N")
			across "abc" as ch loop
				print (ch.item.upper.out)
			end
			print ("%N")
			a := <<"x", "y", "z">>
			across a as c loop
				across 1 |..| c.cursor_index is k loop
					print (c.item)
				end
				print (" ")
			end
			print ("%N")
				-- `until` stops before the first position where it holds.
			print ((across <<1, 2, 3, -4, 5>> as c until c.item < 0 all c.item > 0 end).out + "%N")
			print ((across 1 |..| 10 is i until i > 2 some i = 3 end).out + "%N")
		end

end
