note
	description: "LINKED_QUEUE and ARRAYED_QUEUE: first in, first out; growth and wrap-around."

class
	QUEUES

create
	make

feature {NONE} -- Initialization

	make
		local
			l: LINKED_QUEUE [STRING]
			a: ARRAYED_QUEUE [INTEGER]
			i: INTEGER
		do
			create l.make
			show ("empty", l.is_empty.out + " " + l.count.out)
			l.put ("first")
			l.extend ("second")
			l.force ("third")
			show ("item", l.item + " count " + l.count.out)
			l.remove
			show ("after remove", l.item + " count " + l.count.out)
			show ("has", l.has ("third").out)
			l.compare_objects
			show ("has by object", l.has ("third").out)
			show ("linear_representation", image (l.linear_representation))
			l.replace ("SECOND")
			show ("replace", l.item)
			l.wipe_out
			show ("wipe_out", l.is_empty.out)
			create a.make (2)
			a.put (1)
			a.put (2)
			a.remove
			a.put (3)
			a.put (4)
			show ("wrapped", a.item.out + " count " + a.count.out)
			from
				i := 5
			until
				i > 12
			loop
				a.extend (i)
				i := i + 1
			end
			show ("grown", a.count.out + " item " + a.item.out)
			from
			until
				a.count = 3
			loop
				print (a.item.out + " ")
				a.remove
			end
			print ("%N")
			show ("left", a.item.out + " " + a.count.out + " occurrences of 11: " + a.occurrences (11).out)
		end

feature {NONE} -- Implementation

	image (items: LINEAR [STRING]): STRING
		do
			Result := ""
			from
				items.start
			until
				items.after
			loop
				Result.append (items.item + " ")
				items.forth
			end
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
