note
	description: "[
		Tells the parts of a behaviour that they should stop. A stop request propagates to the
		child signalers (asynchronously, each on its own processor); guards read
		`is_stop_requested'.
	]"

class
	STOP_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- No stop requested, no children.
		do
			create children.make (2)
		ensure
			running: not is_stop_requested
		end

feature -- Status report

	is_stop_requested: BOOLEAN
			-- Should everyone stop?

	child_count: INTEGER
			-- Number of child signalers.
		do
			Result := children.count
		end

feature -- Element change

	add_child (a_child: separate STOP_SIGNALER)
			-- Let a stop of Current also stop `a_child' (at once if already requested).
		do
			children.extend (a_child)
			if is_stop_requested then
				propagate (a_child)
			end
		ensure
			added: child_count = old child_count + 1
		end

feature -- Basic operations

	request_stop
			-- Ask everyone to stop, children included.
		do
			if not is_stop_requested then
				is_stop_requested := True
				across children as c loop
					propagate (c.item)
				end
			end
		ensure
			requested: is_stop_requested
		end

	set_stop_requested (a_value: BOOLEAN)
			-- Ask everyone to stop (`request_stop') when `a_value', else withdraw the request (`reset').
		do
			if a_value then
				request_stop
			else
				reset
			end
		ensure
			set: is_stop_requested = a_value
		end

	reset
			-- Withdraw the stop request (children keep theirs).
		do
			is_stop_requested := False
		ensure
			running: not is_stop_requested
		end

feature {NONE} -- Implementation

	children: ARRAYED_LIST [separate STOP_SIGNALER]
			-- Signalers stopped with Current.

	propagate (a_child: separate STOP_SIGNALER)
			-- Ask `a_child' to stop.
		do
			a_child.request_stop
		end

end
