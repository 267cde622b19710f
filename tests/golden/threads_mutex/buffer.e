note
	description: "A one-slot buffer shared by threads: a mutex and a condition variable."

class
	BUFFER

create
	make

feature {NONE} -- Initialization

	make
		do
			create mutex.make
			create changed.make
		end

feature -- Access

	mutex: MUTEX
	changed: CONDITION_VARIABLE
	item: INTEGER
	full: BOOLEAN

feature -- Basic operations

	put (v: INTEGER)
			-- Wait until the slot is empty, then fill it with `v'.
		do
			mutex.lock
			from until not full loop
				changed.wait (mutex)
			end
			item := v
			full := True
			changed.broadcast
			mutex.unlock
		end

	take: INTEGER
			-- Wait until the slot is full, then empty it.
		do
			mutex.lock
			from until full loop
				changed.wait (mutex)
			end
			Result := item
			full := False
			changed.broadcast
			mutex.unlock
		end

end
