class
	INTEGER_BOUNDARIES

create
	make

feature

	Max8: INTEGER_8 = 127
	Min8: INTEGER_8 = -128
	Max16: INTEGER_16 = 32767
	Min16: INTEGER_16 = -32768
	Max32: INTEGER_32 = 2147483647
	Min32: INTEGER_32 = -2147483648
	Max64: INTEGER_64 = 9223372036854775807
	Min64: INTEGER_64 = -9223372036854775808
	MaxN8: NATURAL_8 = 0xFF
	MaxN16: NATURAL_16 = 0c177777
	MaxN32: NATURAL_32 = 0b11111111111111111111111111111111
	MaxN64: NATURAL_64 = 18446744073709551615

	make
		local
			i: INTEGER
			j: INTEGER_64
			n: NATURAL_64
		do
			i := -2147483648
			j := -9223372036854775808
			n := 0xFFFFFFFFFFFFFFFF
			print (Max8.out + " " + Min8.out + "%N")
			print (Max16.out + " " + Min16.out + "%N")
			print (Max32.out + " " + Min32.out + "%N")
			print (Max64.out + " " + Min64.out + "%N")
			print (MaxN8.out + " " + MaxN16.out + " " + MaxN32.out + " " + MaxN64.out + "%N")
			print (i.out + " " + j.out + " " + n.out + "%N")
			print ((3000000000 + 1).out + "%N")
			print ({INTEGER_64} 9223372036854775807 + 0)
			print ("%N")
		end

end
