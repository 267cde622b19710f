note
	description: "Stacks, a heap priority queue, a sorted list and a set."

class
	CONTAINERS_MORE

create
	make

feature {NONE} -- Initialization

	make
		local
			s: ARRAYED_STACK [INTEGER]
			ls: LINKED_STACK [STRING]
			pq: HEAP_PRIORITY_QUEUE [INTEGER]
			sorted: SORTED_TWO_WAY_LIST [INTEGER]
			set: ARRAYED_SET [STRING]
		do
			create s.make (2)
			s.put (1)
			s.put (2)
			s.extend (3)
			print ("stack top " + s.item.out + " count " + s.count.out + "%N")
			s.remove
			print ("after remove " + s.item.out + ": " + image (s.linear_representation) + "%N")
			create ls.make
			ls.put ("a")
			ls.put ("b")
			print ("linked stack top " + ls.item + " count " + ls.count.out + "%N")
			create pq.make (10)
			across <<5, 1, 9, 3, 7>> is x loop
				pq.put (x)
			end
			print ("priority queue:")
			from
			until
				pq.is_empty
			loop
				print (" " + pq.item.out)
				pq.remove
			end
			print ("%N")
			create sorted.make
			across <<5, 2, 8, 2, 6>> is x loop
				sorted.extend (x)
			end
			print ("sorted: " + image (sorted) + " min " + sorted.min.out + " max " + sorted.max.out + "%N")
			create set.make (4)
			set.compare_objects
			set.extend ("a")
			set.extend ("b")
			set.extend ("a")
			print ("set count " + set.count.out + " has b " + set.has ("b").out + "%N")
		end

feature {NONE} -- Implementation

	image (l: LINEAR [INTEGER]): STRING
		do
			Result := ""
			from
				l.start
			until
				l.after
			loop
				Result.append (l.item.out + " ")
				l.forth
			end
		end

end
