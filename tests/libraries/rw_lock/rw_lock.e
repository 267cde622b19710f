class
	RW_LOCK

create
	make

feature {NONE} -- Initialization

	make
		local
			lock: READ_WRITE_LOCK
			readers: ARRAYED_LIST [READER]
			writer: WRITER
			control: THREAD_CONTROL
			attributes: THREAD_ATTRIBUTES
		do
			create lock.make
			create store.make (0)
			create readers.make (3)
			lock.acquire_write_lock
			across 1 |..| 3 is i loop
				readers.extend (create {READER}.make (lock, store))
			end
			across readers is r loop
				r.launch
			end
			create writer.make (lock, store)
			create attributes.make
			attributes.set_detached (False)
			writer.launch_with_attributes (attributes)
			store.extend (1)
			lock.release_writer_lock
			create control
			control.sleep (1_000_000)
			control.join_all
			across readers is r loop
				print ("reader saw " + r.seen.out + " item(s)%N")
			end
			print ("store: " + store.count.out + " items, writer terminated: " + writer.terminated.out + "%N")
			print ("priority: " + attributes.priority.out + ", detached: " + attributes.detached.out + "%N")
		end

	store: ARRAYED_LIST [INTEGER]

end
