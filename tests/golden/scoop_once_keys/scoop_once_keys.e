note
	description: "[
		Once keys in a SCOOP system: a once (%"PROCESS%") function's separate result is one object for
		every processor, used as a call target; a once (%"OBJECT%") function has one result per object,
		called through separate targets; its result used as a call target in its region.
	]"

class SCOOP_ONCE_KEYS
inherit SHARED_BOARD
create make
feature
	make
		local
			w1, w2: separate WORKER
		do
			create w1
			create w2
			run (w1, 1)
			run (w2, 10)
			print ("total " + total.out + "%N")
			print ("object tags " + object_tag (w1, 1).out + " " + object_tag (w2, 2).out + " " + object_tag (w1, 3).out + "%N")
			print ("process tags " + process_tag (w1, 1).out + " " + process_tag (w2, 2).out + "%N")
			print ("stamps " + stamp_of (w1, 7) + " " + stamp_of (w2, 8) + " " + stamp_of (w1, 9) + "%N")
			print ("shared " + same_board (w1, w2).out + "%N")
		end
	run (w: separate WORKER; n: INTEGER) do w.work (n); print ("worker done: " + w.own_count.out + "%N") end
	object_tag (w: separate WORKER; t: INTEGER): INTEGER do Result := w.first_tag (t) end
	process_tag (w: separate WORKER; t: INTEGER): INTEGER do Result := w.process_tag (t) end
	stamp_of (w: separate WORKER; t: INTEGER): STRING
		do
			w.set_tag (t)
			create Result.make_from_separate (w.stamp)
		end
	same_board (w1, w2: separate WORKER): BOOLEAN do Result := w1.board = w2.board and w1.board = board end
	total: INTEGER
		do
			separate board as b do Result := b.count end
		end
end
