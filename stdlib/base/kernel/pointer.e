note
	description: "[
		Addresses of memory outside the Eiffel object model. Python has no
		addresses: a POINTER holds an opaque host value (default: the null pointer)
		and is useful only to pass through externals.
	]"

frozen expanded class
	POINTER

inherit
	HASHABLE
		redefine
			is_hashable, is_equal, out
		end

feature -- Access

	item: POINTER
			-- The value itself.
		external
			"built_in"
		end

	hash_code: INTEGER_32
			-- Hash code value.
		external
			"built_in"
		end

feature -- Status report

	is_hashable: BOOLEAN
			-- May the current pointer be hashed (is it not null)?
		external
			"built_in"
		end

	is_default_pointer: BOOLEAN
			-- Is the current pointer the null pointer?
		external
			"built_in"
		end

feature -- Comparison

	is_equal (other: POINTER): BOOLEAN
			-- Is `other' the same address?
		external
			"built_in"
		end

feature -- Operations

	plus alias "+" (offset: INTEGER_32): POINTER
			-- Address `offset' bytes further.
		external
			"built_in"
		end

feature -- Conversion

	to_integer_32: INTEGER_32
			-- The address as an integer.
		external
			"built_in"
		end

feature -- Output

	out: STRING_8
			-- Hexadecimal representation of the address.
		external
			"built_in"
		end

end
