note
	description: "[
		Sequences of values of possibly different types: `TUPLE [A, B]' holds an A at
		index 1 and a B at index 2 (labels, as in `TUPLE [name: STRING]', name the
		indices). `[a, b]' is a manifest tuple. Items are read with `item' and the typed
		queries (`integer_item', ...), changed with `put' or through labels.
	]"
	implementation: "[
		The storage is the host's: `count', `item', `put', `item_code',
		`valid_type_for_index', `object_comparison' and the two comparison setters are
		`external "Python"'. The compiler gives tuple types their actual generics and
		labels; this class is the base class of all of them.
	]"

class
	TUPLE

inherit
	HASHABLE
		redefine
			is_equal
		end

	READABLE_INDEXABLE [detachable separate ANY]
		redefine
			is_equal
		end

create
	default_create

feature -- Access

	item alias "[]", at alias "@" (index: INTEGER_32): detachable separate ANY assign put
			-- Item at `index'.
		external
			"Python"
		end

	reference_item (index: INTEGER_32): detachable separate ANY
			-- Item at `index', of a reference type.
		require
			valid_index: valid_index (index)
			is_reference: is_reference_item (index)
		do
			Result := item (index)
		end

	boolean_item (index: INTEGER_32): BOOLEAN
			-- BOOLEAN item at `index'.
		require
			valid_index: valid_index (index)
			is_boolean: is_boolean_item (index)
		do
			if attached {BOOLEAN} item (index) as v then
				Result := v
			end
		end

	character_8_item, character_item (index: INTEGER_32): CHARACTER_8
			-- CHARACTER_8 item at `index'.
		require
			valid_index: valid_index (index)
			is_character_8: is_character_8_item (index)
		do
			if attached {CHARACTER_8} item (index) as v then
				Result := v
			end
		end

	character_32_item, wide_character_item (index: INTEGER_32): CHARACTER_32
			-- CHARACTER_32 item at `index'.
		require
			valid_index: valid_index (index)
			is_character_32: is_character_32_item (index)
		do
			if attached {CHARACTER_32} item (index) as v then
				Result := v
			end
		end

	real_64_item, double_item (index: INTEGER_32): REAL_64
			-- REAL_64 item at `index'.
		require
			valid_index: valid_index (index)
			is_numeric: is_double_item (index)
		do
			if attached {REAL_64} item (index) as v then
				Result := v
			end
		end

	real_32_item, real_item (index: INTEGER_32): REAL_32
			-- REAL_32 item at `index'.
		require
			valid_index: valid_index (index)
			is_real: is_real_item (index)
		do
			if attached {REAL_32} item (index) as v then
				Result := v
			end
		end

	natural_8_item (index: INTEGER_32): NATURAL_8
			-- NATURAL_8 item at `index'.
		require
			valid_index: valid_index (index)
			is_natural_8: is_natural_8_item (index)
		do
			if attached {NATURAL_8} item (index) as v then
				Result := v
			end
		end

	natural_16_item (index: INTEGER_32): NATURAL_16
			-- NATURAL_16 item at `index'.
		require
			valid_index: valid_index (index)
			is_natural_16: is_natural_16_item (index)
		do
			if attached {NATURAL_16} item (index) as v then
				Result := v
			end
		end

	natural_32_item (index: INTEGER_32): NATURAL_32
			-- NATURAL_32 item at `index'.
		require
			valid_index: valid_index (index)
			is_natural_32: is_natural_32_item (index)
		do
			if attached {NATURAL_32} item (index) as v then
				Result := v
			end
		end

	natural_64_item (index: INTEGER_32): NATURAL_64
			-- NATURAL_64 item at `index'.
		require
			valid_index: valid_index (index)
			is_natural_64: is_natural_64_item (index)
		do
			if attached {NATURAL_64} item (index) as v then
				Result := v
			end
		end

	integer_8_item (index: INTEGER_32): INTEGER_8
			-- INTEGER_8 item at `index'.
		require
			valid_index: valid_index (index)
			is_integer_8: is_integer_8_item (index)
		do
			if attached {INTEGER_8} item (index) as v then
				Result := v
			end
		end

	integer_16_item (index: INTEGER_32): INTEGER_16
			-- INTEGER_16 item at `index'.
		require
			valid_index: valid_index (index)
			is_integer_16: is_integer_16_item (index)
		do
			if attached {INTEGER_16} item (index) as v then
				Result := v
			end
		end

	integer_item, integer_32_item (index: INTEGER_32): INTEGER_32
			-- INTEGER_32 item at `index'.
		require
			valid_index: valid_index (index)
			is_integer: is_integer_32_item (index)
		do
			if attached {INTEGER_32} item (index) as v then
				Result := v
			end
		end

	integer_64_item (index: INTEGER_32): INTEGER_64
			-- INTEGER_64 item at `index'.
		require
			valid_index: valid_index (index)
			is_integer_64: is_integer_64_item (index)
		do
			if attached {INTEGER_64} item (index) as v then
				Result := v
			end
		end

	item_code (index: INTEGER_32): NATURAL_8
			-- Code of the declared type of the item at `index' (see the `..._code' constants).
		require
			valid_index: valid_index (index)
		external
			"Python"
		end

feature -- Measurement

	count: INTEGER_32
			-- Number of items.
		external
			"Python"
		end

	lower: INTEGER_32 = 1
			-- Index of the first item.

	upper: INTEGER_32
			-- Index of the last item.
		do
			Result := count
		end

feature -- Comparison

	object_comparison: BOOLEAN
			-- Does `is_equal' compare reference items with `~' rather than `='?
		external
			"Python"
		end

	is_equal (other: like Current): BOOLEAN
			-- Do the current tuple and `other' hold the same items
			-- (compared with `~' if `object_comparison', otherwise with `=')?
		local
			i, n: INTEGER_32
		do
			n := count
			if n = other.count and object_comparison = other.object_comparison then
				from
					Result := True
					i := 1
				until
					i > n or not Result
				loop
					if object_comparison then
						Result := item (i) ~ other.item (i)
					else
						Result := item (i) = other.item (i)
					end
					i := i + 1
				end
			end
		end

feature -- Status setting

	compare_objects
			-- Make `is_equal' compare reference items with `~'.
		external
			"Python"
		ensure
			object_comparison: object_comparison
		end

	compare_references
			-- Make `is_equal' compare reference items with `='.
		external
			"Python"
		ensure
			reference_comparison: not object_comparison
		end

feature -- Status report

	hash_code: INTEGER_32
			-- Hash code combining those of the items.
		local
			i, n: INTEGER_32
		do
			from
				i := 1
				n := count
			until
				i > n
			loop
				if attached {HASHABLE} item (i) as h then
					Result := ((Result \\ 1000003) * 31 + h.hash_code \\ 1000003) \\ 1073741823
				end
				i := i + 1
			end
		end

	valid_index (k: INTEGER_32): BOOLEAN
			-- Is `k' between 1 and `count'?
		do
			Result := 1 <= k and k <= count
		end

	is_empty: BOOLEAN
			-- Is there no item?
		do
			Result := count = 0
		end

	valid_type_for_index (v: detachable separate ANY; index: INTEGER_32): BOOLEAN
			-- May `v' be put at `index' (does it conform to the declared type there)?
		require
			valid_index: valid_index (index)
		external
			"Python"
		end

feature -- Type queries

	is_reference_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' of a reference type?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = reference_code
		end

	is_boolean_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a BOOLEAN?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = boolean_code
		end

	is_character_8_item, is_character_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a CHARACTER_8?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = character_8_code
		end

	is_character_32_item, is_wide_character_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a CHARACTER_32?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = character_32_code
		end

	is_double_item, is_real_64_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a REAL_64?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = real_64_code
		end

	is_real_item, is_real_32_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a REAL_32?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = real_32_code
		end

	is_natural_8_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a NATURAL_8?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = natural_8_code
		end

	is_natural_16_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a NATURAL_16?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = natural_16_code
		end

	is_natural_32_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a NATURAL_32?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = natural_32_code
		end

	is_natural_64_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a NATURAL_64?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = natural_64_code
		end

	is_integer_8_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' an INTEGER_8?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = integer_8_code
		end

	is_integer_16_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' an INTEGER_16?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = integer_16_code
		end

	is_integer_item, is_integer_32_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' an INTEGER_32?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = integer_32_code
		end

	is_integer_64_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' an INTEGER_64?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = integer_64_code
		end

	is_pointer_item (index: INTEGER_32): BOOLEAN
			-- Is the item at `index' a POINTER?
		require
			valid_index: valid_index (index)
		do
			Result := item_code (index) = pointer_code
		end

feature -- Element change

	put (v: detachable separate ANY; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type_for_index: valid_type_for_index (v, index)
		external
			"Python"
		end

	put_reference (v: detachable separate ANY; index: INTEGER_32)
			-- Put `v' at `index', of a reference type.
		require
			valid_index: valid_index (index)
			valid_type_for_index: valid_type_for_index (v, index)
			valid_type: is_reference_item (index)
		do
			put (v, index)
		end

	put_boolean (v: BOOLEAN; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_boolean_item (index)
		do
			put (v, index)
		end

	put_character_8, put_character (v: CHARACTER_8; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_character_8_item (index)
		do
			put (v, index)
		end

	put_character_32, put_wide_character (v: CHARACTER_32; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_character_32_item (index)
		do
			put (v, index)
		end

	put_real_64, put_double (v: REAL_64; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_double_item (index)
		do
			put (v, index)
		end

	put_real_32, put_real (v: REAL_32; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_real_item (index)
		do
			put (v, index)
		end

	put_natural_8 (v: NATURAL_8; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_natural_8_item (index)
		do
			put (v, index)
		end

	put_natural_16 (v: NATURAL_16; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_natural_16_item (index)
		do
			put (v, index)
		end

	put_natural_32 (v: NATURAL_32; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_natural_32_item (index)
		do
			put (v, index)
		end

	put_natural_64 (v: NATURAL_64; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_natural_64_item (index)
		do
			put (v, index)
		end

	put_integer_8 (v: INTEGER_8; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_integer_8_item (index)
		do
			put (v, index)
		end

	put_integer_16 (v: INTEGER_16; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_integer_16_item (index)
		do
			put (v, index)
		end

	put_integer, put_integer_32 (v: INTEGER_32; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_integer_32_item (index)
		do
			put (v, index)
		end

	put_integer_64 (v: INTEGER_64; index: INTEGER_32)
			-- Put `v' at `index'.
		require
			valid_index: valid_index (index)
			valid_type: is_integer_64_item (index)
		do
			put (v, index)
		end

feature -- Conversion

	arrayed: ARRAY [detachable separate ANY]
			-- The items, in an array indexed from 1.
		local
			i: INTEGER_32
		do
			create Result.make_filled (Void, 1, count)
			from
				i := 1
			until
				i > count
			loop
				Result.put (item (i), i)
				i := i + 1
			end
		ensure
			same_count: Result.count = count
		end

feature -- Type codes

	reference_code: NATURAL_8 = 0
	boolean_code: NATURAL_8 = 1
	character_8_code, character_code: NATURAL_8 = 2
	real_64_code: NATURAL_8 = 3
	real_32_code: NATURAL_8 = 4
	pointer_code: NATURAL_8 = 5
	integer_8_code: NATURAL_8 = 6
	integer_16_code: NATURAL_8 = 7
	integer_32_code: NATURAL_8 = 8
	integer_64_code: NATURAL_8 = 9
	natural_8_code: NATURAL_8 = 10
	natural_16_code: NATURAL_8 = 11
	natural_32_code: NATURAL_8 = 12
	natural_64_code: NATURAL_8 = 13
	character_32_code, wide_character_code: NATURAL_8 = 14
			-- Values of `item_code' for each kind of declared type.

end
