class
	STOP

create
	make

feature

	make
			-- A root signaler with two children and a grandchild; stop the root.
		local
			root, a, b, c: separate STOP_SIGNALER
		do
			create root.make
			create a.make
			create b.make
			create c.make
			link (root, a)
			link (root, b)
			link (a, c)
			stop (root)
			report (a, b, c)
		end

	link (p, c: separate STOP_SIGNALER)
		do
			p.add_child (c)
		end

	stop (s: separate STOP_SIGNALER)
		do
			s.request_stop
		end

	report (a, b, c: separate STOP_SIGNALER)
		require
			a.is_stop_requested and b.is_stop_requested and c.is_stop_requested
		do
			print ("all stopped%N")
		end

end
