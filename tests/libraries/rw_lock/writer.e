class
	WRITER

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

	execute
		do
			sleep (20_000_000)
			lock.acquire_write_lock
			store.extend (2)
			lock.release_writer_lock
		end

end
