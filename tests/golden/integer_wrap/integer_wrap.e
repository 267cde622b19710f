note
	description: "Integer arithmetic of every size: wrap-around, division toward zero, bits, conversions."

class
	INTEGER_WRAP

create
	make

feature {NONE} -- Initialization

	make
		local
			i8: INTEGER_8
			i16: INTEGER_16
			i32: INTEGER_32
			i64: INTEGER_64
			n8: NATURAL_8
			n16: NATURAL_16
			n32: NATURAL_32
			n64: NATURAL_64
		do
			i8 := 127
			i8 := i8 + 1
			show ("i8 127 + 1", i8.out)
			i8 := i8 - 1
			show ("i8 -128 - 1", i8.out)
			i8 := 100
			i8 := i8 * 3
			show ("i8 100 * 3", i8.out)
			i8 := -128
			i8 := i8 // -1
			show ("i8 -128 // -1", i8.out)
			i8 := -128
			show ("i8 abs", i8.abs.out)
			i16 := 32767
			i16 := i16 + 2
			show ("i16 32767 + 2", i16.out)
			i32 := {INTEGER_32}.max_value
			i32 := i32 + 1
			show ("i32 max + 1", i32.out)
			i32 := 65536
			i32 := i32 * 65536
			show ("i32 65536 * 65536", i32.out)
			i32 := {INTEGER_32}.min_value
			show ("i32 min - 1", (i32 - 1).out)
			i32 := 65536
			show ("i32 65536 * 65536 + 7 - 3", (i32 * 65536 + 7 - 3).out)
			i32 := {INTEGER_32}.max_value
			i32 := i32 + 1 - 1
			show ("i32 max + 1 - 1", i32.out)
			i32 := i32 + 5 - 1
			show ("i32 max + 5 - 1", i32.out)
			i8 := 100
			i8 := i8 * 3 - -(i8 * 2)
			show ("i8 100 * 3 - -(100 * 2)", i8.out)
			i64 := {INTEGER_64}.max_value
			i64 := i64 + 1
			show ("i64 max + 1", i64.out)
			i64 := 3_000_000_000
			i64 := i64 * 4_000_000_000
			show ("i64 3e9 * 4e9", i64.out)
			n8 := 0
			n8 := n8 - 1
			show ("n8 0 - 1", n8.out)
			n8 := 200
			n8 := n8 + 100
			show ("n8 200 + 100", n8.out)
			n16 := 65535
			n16 := n16 + 1
			show ("n16 65535 + 1", n16.out)
			n32 := 0
			n32 := n32 - 1
			show ("n32 0 - 1", n32.out)
			n32 := 7
			show ("n32 7 // 2, 7 \\ 2", (n32 // 2).out + " " + (n32 \\ 2).out)
			n64 := 0
			n64 := n64 - 1
			show ("n64 0 - 1", n64.out)
			n64 := {NATURAL_64} 18_446_744_073_709_551_615
			show ("n64 max // 3", (n64 // 3).out)
			show ("n64 max + 2", (n64 + 2).out)
			show ("7 // 2, -7 // 2, 7 // -2, -7 // -2", (7 // 2).out + " " + (-7 // 2).out + " " + (7 // -2).out + " " + (-7 // -2).out)
			show ("7 \\ 2, -7 \\ 2, 7 \\ -2, -7 \\ -2", (7 \\ 2).out + " " + (-7 \\ 2).out + " " + (7 \\ -2).out + " " + (-7 \\ -2).out)
			i64 := -9
			show ("i64 -9 // 4, -9 \\ 4", (i64 // 4).out + " " + (i64 \\ 4).out)
			show ("7 / 2", (7 / 2).out)
			show ("2 ^ 10", (2 ^ 10).out)
			show ("-7 abs, 7 max 9, 3 min -2", (-7).abs.out + " " + (7).max (9).out + " " + (3).min (-2).out)
			show ("sign", (-5).sign.out + " " + (0).sign.out + " " + (5).sign.out)
			show ("12 & 10, 12 | 10, 12 xor 10", (12 & 10).out + " " + (12 | 10).out + " " + (12).bit_xor (10).out)
			show ("1 |<< 4, 1 |<< 31, -16 |>> 2", (1 |<< 4).out + " " + (1 |<< 31).out + " " + (-16 |>> 2).out)
			show ("bit_not 0", (0).bit_not.out)
			n8 := 0
			show ("n8 bit_not 0", n8.bit_not.out)
			show ("bit_test", (5).bit_test (0).out + " " + (5).bit_test (1).out)
			show ("to_hex_string", (10).to_hex_string + " " + (-1).to_hex_string)
			n8 := 255
			show ("n8 to_hex_string", n8.to_hex_string)
			show ("as_integer_8 300, as_natural_8 -1", (300).as_integer_8.out + " " + (-1).as_natural_8.out)
			show ("as_natural_32 -1", (-1).as_natural_32.out)
			n8 := 200
			show ("n8 200 as_integer_8", n8.as_integer_8.out)
			i8 := -128
			i32 := 1000
			show ("i8 + i32", (i8 + i32).out)
			show ("0xFF, 1_000_000", (0xFF).out + " " + (1_000_000).out)
			show ("to_real_64 / 2", ((7).to_real_64 / 2).out)
			show ("comparisons", (3 < 5).out + " " + (3 >= 5).out + " " + (3).three_way_comparison (5).out)
			show ("hash_code -5", (-5).hash_code.out)
			show ("is_valid_character_8_code", (65).to_character_8.out + " " + (256).is_valid_character_8_code.out)
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
