class WORKER
inherit SHARED_BOARD
feature
	work (n: INTEGER)
		do
			separate board as b do b.add (n) end
		end
	own_board: TALLY_BOARD
		once ("OBJECT")
			create Result
		end
	first_tag (t: INTEGER): INTEGER
		once ("OBJECT")
			Result := t
		end
	process_tag (t: INTEGER): INTEGER
		once ("PROCESS")
			Result := t
		end
	stamp: STRING
		once ("OBJECT")
			Result := "stamp of " + tag.out
		end
	tag: INTEGER
	set_tag (t: INTEGER) do tag := t end
	bump
		do
			own_board.add (1)
		end
	own_count: INTEGER
		do
			Result := own_board.count
		end
end
