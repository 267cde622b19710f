note
	description: "[
		Pseudo-random integers in 0 .. `modulus' - 1, as an endless sequence: `start',
		`forth', `item', or the `i'-th number with `i_th'. The same seed gives the same
		numbers as EiffelStudio's RANDOM: the Park-Miller minimal standard generator
		(next = 16807 * previous mod (2^31 - 1)), default seed 123457.
	]"
	implementation: "Plain Eiffel: the product is computed on INTEGER_64, where it is exact."

class
	RANDOM

create
	make,
	set_seed

feature -- Initialization

	make
			-- Sequence from `default_seed', positioned on its first number.
		do
			set_seed (default_seed)
			start
		ensure
			seed_set: seed = default_seed
		end

	set_seed (s: INTEGER_32)
			-- Restart the sequence from seed `s'.
		require
			non_negative: s >= 0
		do
			seed := s
			last_result := s
			last_item := 0
		ensure
			seed_set: seed = s
		end

feature -- Access

	default_seed: INTEGER_32
			-- Seed used by `make'.
		do
			Result := 123_457
		end

	modulus: INTEGER_32
			-- Bound of the numbers: 2^31 - 1.
		do
			Result := 2_147_483_647
		end

	multiplier: INTEGER_32
			-- Multiplier of the generator: 7^5.
		do
			Result := 16_807
		end

	increment: INTEGER_32
			-- Increment of the generator (none).
		do
			Result := 0
		end

	seed: INTEGER_32
			-- Seed of the sequence.

	index: INTEGER_32
			-- Position in the sequence.

	item: INTEGER_32
			-- Number at the current position.
		do
			Result := i_th (index)
		end

	i_th (i: INTEGER_32): INTEGER_32
			-- The `i'-th number of the sequence (the seed for 0).
		require
			non_negative_index: i >= 0
		local
			n: INTEGER_32
		do
			if i >= last_item then
				Result := last_result
				n := last_item
			else
				Result := seed
			end
			from
			until
				n = i
			loop
				Result := randomize (Result)
				n := n + 1
			end
			last_result := Result
			last_item := i
		ensure
			in_range: Result >= 0 and Result < modulus
		end

	next_random (n: INTEGER_32): INTEGER_32
			-- The number that follows `n' in the sequence.
		require
			in_range: n >= 0 and n < modulus
		do
			Result := randomize (n)
		ensure
			in_range: Result >= 0 and Result < modulus
		end

	real_item: REAL_32
			-- Number at the current position, scaled to a REAL_32 in [0, 1).
		local
			r1, r2: REAL_32
		do
			r1 := item
			r2 := modulus
			Result := r1 / r2
		end

	double_item: REAL_64
			-- Number at the current position, scaled to a REAL_64 in [0, 1).
		local
			d: REAL_64
		do
			d := item
			Result := d / modulus
		end

	real_i_th (i: INTEGER_32): REAL_32
			-- The `i'-th number, scaled to a REAL_32 in [0, 1).
		require
			positive_argument: i > 0
		local
			r1, r2: REAL_32
		do
			r1 := i_th (i)
			r2 := modulus
			Result := r1 / r2
		end

	double_i_th (i: INTEGER_32): REAL_64
			-- The `i'-th number, scaled to a REAL_64 in [0, 1).
		require
			positive_argument: i > 0
		local
			d: REAL_64
		do
			d := i_th (i)
			Result := d / modulus
		end

feature -- Status report

	has (n: INTEGER_32): BOOLEAN
			-- May `n' appear in the sequence?
		do
			Result := n >= 0 and n < modulus
		end

	after: BOOLEAN
			-- Is the position past the end? (Never: the sequence is endless.)
		do
			Result := False
		end

	off: BOOLEAN
			-- Is there no number at the current position? (Only before `start'.)
		do
			Result := index = 0
		end

feature -- Cursor movement

	start
			-- Go to the first number of the sequence.
		do
			index := 1
		end

	forth
			-- Go to the next number.
		do
			index := index + 1
		end

feature {NONE} -- Implementation

	randomize (xn: INTEGER_32): INTEGER_32
			-- The number that follows `xn'.
		local
			x: INTEGER_64
		do
			x := multiplier.to_integer_64 * xn + increment
			Result := (x \\ modulus).to_integer_32
		end

	last_item: INTEGER_32
			-- Position of the last number computed by `i_th'.

	last_result: INTEGER_32
			-- Last number computed by `i_th'.

invariant
	non_negative_seed: seed >= 0
	non_negative_increment: increment >= 0
	positive_multiplier: multiplier > 0
	modulus_constraint: modulus > 1

end
