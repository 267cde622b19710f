class
	READER

inherit
	THREAD
		rename
			make as thread_make
		end

create
	make

feature {NONE} -- Initialization

	make (a_lock: READ_WRITE_LOCK; a_store: ARRAYED_LIST [INTEGER])
		do
			thread_make
			lock := a_lock
			store := a_store
		end

feature

	lock: READ_WRITE_LOCK
	store: ARRAYED_LIST [INTEGER]
	seen: INTEGER

	execute
		do
			lock.acquire_read_lock
			seen := store.count
			lock.release_reader_lock
		end

end
