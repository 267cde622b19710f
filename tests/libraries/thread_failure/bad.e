class BAD
inherit THREAD
create make_bad
feature
	make_bad do make; create m.make end
	m: MUTEX
	execute
		do
			m.unlock
		end
end
