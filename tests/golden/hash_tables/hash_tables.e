note
	description: "HASH_TABLE: put, force, item, has, remove, search; iteration order (EiffelBase's layout)."

class
	HASH_TABLES

create
	make

feature {NONE} -- Initialization

	make
		local
			t: HASH_TABLE [INTEGER, STRING]
			n: HASH_TABLE [STRING, INTEGER]
			keys: ARRAY [STRING]
		do
			create t.make (3)
			t.put (1, "one")
			t.put (2, "two")
			t.put (3, "three")
			show ("count", t.count.out + " inserted " + t.inserted.out)
			t.put (33, "three")
			show ("put existing", t.inserted.out + " " + t.conflict.out + " found_item " + t.found_item.out + " item " + t ["three"].out)
			t.force (30, "three")
			show ("force existing", t.item ("three").out + " found " + t.found.out + " count " + t.count.out)
			show ("item, absent", t.item ("two").out + " " + t ["zero"].out)
			show ("has", t.has ("one").out + " " + t.has ("four").out + " " + t.has_item (30).out)
			print_table (t)
			t.remove ("two")
			show ("remove", t.removed.out + " count " + t.count.out + " has " + t.has ("two").out)
			t.remove ("two")
			show ("remove again", t.removed.out + " " + t.not_found.out)
			t.put (4, "four")
			print_table (t)
			t.put (5, "five")
			t.force (6, "six")
			t.extend (7, "seven")
			print_table (t)
			t.search ("five")
			show ("search five", t.found.out + " " + t.found_item.out)
			t.search ("nine")
			show ("search nine", t.found.out + " " + t.found_item.out)
			t ["one"] := 100
			show ("assigner", t ["one"].out)
			t.replace (300, "three")
			t.replace_key ("drei", "three")
			show ("replace_key", t.has ("three").out + " " + t ["drei"].out)
			print_table (t)
			keys := t.current_keys
			show ("current_keys", keys.count.out + " first " + keys [1] + " last " + keys [keys.count])
			from
				t.start
			until
				t.after
			loop
				print (t.key_for_iteration + ":" + t.item_for_iteration.out + " ")
				t.forth
			end
			print ("%N")
			create n.make (10)
			across <<10, 3, 0, 25, 100003, 7>> is k loop
				n.put ("v" + k.out, k)
			end
			n.remove (3)
			n.put ("again", 3)
			across n as c loop
				print (c.key.out + "->" + c.item + " ")
			end
			print ("%N")
			if attached n [0] as v then
				show ("default key", n.has (0).out + " " + v)
			end
			n.remove (0)
			show ("default key removed", n.has (0).out + " count " + n.count.out)
			n.wipe_out
			show ("wipe_out", n.count.out + " " + n.is_empty.out)
		end

feature {NONE} -- Implementation

	print_table (t: HASH_TABLE [INTEGER, STRING])
		do
			across t as c loop
				print (c.key + "=" + c.item.out + " ")
			end
			print ("%N")
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
