note
	description: "A worker that fills a block of bytes and checksums it with the sample's C library."

class
	CHECKSUM_WORKER

create
	make

feature {NONE} -- Initialization

	make (a_index, a_size: INTEGER)
			-- Worker for block `a_index' of `a_size' bytes.
		require
			positive_size: a_size > 0
		do
			index := a_index
			seed := (a_index * 7919).to_natural_32
			create block.make_filled (0, a_size)
		end

feature -- Access

	index: INTEGER
			-- Number of the block.

	seed: NATURAL_32
			-- Seed of the block's pseudo-random bytes.

	crc: NATURAL_32
			-- CRC-32 of the block, once computed.

feature -- Basic operations

	compute
			-- Fill the block and checksum it, both in C.
		do
			fill (block, block.count, seed)
			crc := crc32 (block, block.count)
		end

feature {NONE} -- Implementation

	block: SPECIAL [NATURAL_8]
			-- The data.

	fill (a_block: SPECIAL [NATURAL_8]; a_count: INTEGER; a_seed: NATURAL_32)
			-- Fill `a_block' with `a_count' pseudo-random bytes from `a_seed'.
		external
			"C use %"checksum.h%""
		alias
			"checksum_fill"
		end

	crc32 (a_block: SPECIAL [NATURAL_8]; a_count: INTEGER): NATURAL_32
			-- CRC-32 (the zlib polynomial) of the first `a_count' bytes of `a_block'.
		external
			"C blocking use %"checksum.h%""
		alias
			"checksum_crc32"
		end

end
