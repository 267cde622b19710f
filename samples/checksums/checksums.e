note
	description: "[
		CRC-32 checksums of data blocks computed by a small C library of the sample's own
		(checksum.c, named in checksums.ecf and built by scoopc): each worker, on its own
		processor, fills a block in C and checksums it in C; the workers' C calls run at the
		same time. The root collects the checksums.
	]"

class
	CHECKSUMS

create
	make

feature {NONE} -- Initialization

	make
			-- Start one worker per block, then print each block's checksum.
		local
			l_workers: ARRAYED_LIST [separate CHECKSUM_WORKER]
			l_worker: separate CHECKSUM_WORKER
			i: INTEGER
		do
			create l_workers.make (Block_count)
			from i := 1 until i > Block_count loop
				create l_worker.make (i, Block_size)
				start (l_worker)
				l_workers.extend (l_worker)
				i := i + 1
			end
			across l_workers as c loop
				report (c.item)
			end
			print ("Checksummed " + Block_count.out + " blocks of " + Block_size.out + " bytes%N")
		end

feature {NONE} -- Implementation

	Block_count: INTEGER = 4
			-- How many blocks (and workers).

	Block_size: INTEGER = 50_000
			-- Bytes per block.

	start (a_worker: separate CHECKSUM_WORKER)
			-- Let `a_worker' fill and checksum its block.
		do
			a_worker.compute
		end

	report (a_worker: separate CHECKSUM_WORKER)
			-- Print `a_worker''s checksum, once it is done.
		do
			print ("Block " + a_worker.index.out + " (seed " + a_worker.seed.out + "): crc32 " + a_worker.crc.out + "%N")
		end

end
