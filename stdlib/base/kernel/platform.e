note
	description: "Properties of the platform: sizes of the basic types and the operating system."

class
	PLATFORM

feature -- Platform

	is_thread_capable: BOOLEAN = True
			-- Can the program use threads? (Yes.)

	is_scoop_capable: BOOLEAN = True
			-- Does the program run with SCOOP? (Yes.)

	is_dotnet: BOOLEAN = False
			-- Is the program running on .NET? (No.)

	is_windows: BOOLEAN
			-- Is the operating system Windows?
		external
			"Python"
		end

	is_unix: BOOLEAN
			-- Is the operating system a Unix (Linux, macOS, ...)?
		external
			"Python"
		end

	is_mac: BOOLEAN
			-- Is the operating system macOS?
		external
			"Python"
		end

	is_vms: BOOLEAN = False
			-- Is the operating system VMS? (No.)

	is_vxworks: BOOLEAN = False
			-- Is the operating system VxWorks? (No.)

	is_little_endian: BOOLEAN
			-- Is the machine little-endian?
		external
			"Python"
		end

	is_64_bits: BOOLEAN
			-- Is the machine 64-bit?
		external
			"Python"
		end

feature -- Access bytes size

	boolean_bytes: INTEGER_32 = 1
			-- Bytes of a BOOLEAN.

	character_8_bytes: INTEGER_32 = 1
			-- Bytes of a CHARACTER_8.

	character_32_bytes: INTEGER_32 = 4
			-- Bytes of a CHARACTER_32.

	natural_8_bytes: INTEGER_32 = 1
			-- Bytes of a NATURAL_8.

	natural_16_bytes: INTEGER_32 = 2
			-- Bytes of a NATURAL_16.

	natural_32_bytes: INTEGER_32 = 4
			-- Bytes of a NATURAL_32.

	natural_64_bytes: INTEGER_32 = 8
			-- Bytes of a NATURAL_64.

	integer_8_bytes: INTEGER_32 = 1
			-- Bytes of an INTEGER_8.

	integer_16_bytes: INTEGER_32 = 2
			-- Bytes of an INTEGER_16.

	integer_32_bytes: INTEGER_32 = 4
			-- Bytes of an INTEGER_32.

	integer_64_bytes: INTEGER_32 = 8
			-- Bytes of an INTEGER_64.

	real_32_bytes: INTEGER_32 = 4
			-- Bytes of a REAL_32.

	real_64_bytes: INTEGER_32 = 8
			-- Bytes of a REAL_64.

	pointer_bytes: INTEGER_32 = 8
			-- Bytes of a POINTER.

feature -- Access bits size

	boolean_bits: INTEGER_32 = 8
			-- Bits of a BOOLEAN.

	character_8_bits: INTEGER_32 = 8
			-- Bits of a CHARACTER_8.

	character_32_bits: INTEGER_32 = 32
			-- Bits of a CHARACTER_32.

	natural_8_bits: INTEGER_32 = 8
			-- Bits of a NATURAL_8.

	natural_16_bits: INTEGER_32 = 16
			-- Bits of a NATURAL_16.

	natural_32_bits: INTEGER_32 = 32
			-- Bits of a NATURAL_32.

	natural_64_bits: INTEGER_32 = 64
			-- Bits of a NATURAL_64.

	integer_8_bits: INTEGER_32 = 8
			-- Bits of an INTEGER_8.

	integer_16_bits: INTEGER_32 = 16
			-- Bits of an INTEGER_16.

	integer_32_bits: INTEGER_32 = 32
			-- Bits of an INTEGER_32.

	integer_64_bits: INTEGER_32 = 64
			-- Bits of an INTEGER_64.

	real_32_bits: INTEGER_32 = 32
			-- Bits of a REAL_32.

	real_64_bits: INTEGER_32 = 64
			-- Bits of a REAL_64.

	pointer_bits: INTEGER_32 = 64
			-- Bits of a POINTER.

feature -- Older names

	character_bytes: INTEGER_32 = 1
			-- Bytes of a CHARACTER_8.

	wide_character_bytes: INTEGER_32 = 4
			-- Bytes of a CHARACTER_32.

	integer_bytes: INTEGER_32 = 4
			-- Bytes of an INTEGER_32.

	real_bytes: INTEGER_32 = 4
			-- Bytes of a REAL_32.

	double_bytes: INTEGER_32 = 8
			-- Bytes of a REAL_64.

	character_bits: INTEGER_32 = 8
			-- Bits of a CHARACTER_8.

	integer_bits: INTEGER_32 = 32
			-- Bits of an INTEGER_32.

	real_bits: INTEGER_32 = 32
			-- Bits of a REAL_32.

	double_bits: INTEGER_32 = 64
			-- Bits of a REAL_64.

	maximum_character_code: INTEGER_32 = 255
			-- Largest CHARACTER_8 code.

	minimum_character_code: INTEGER_32 = 0
			-- Smallest CHARACTER_8 code.

	maximum_integer: INTEGER_32 = 2147483647
			-- Largest INTEGER_32.

	minimum_integer: INTEGER_32 = -2147483648
			-- Smallest INTEGER_32.

end
