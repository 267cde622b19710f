class
	APPLICATION

create
	make

feature -- Constants

	Over_8: INTEGER_8 = 128 -- E: VQMC(3)@22
	Under_8: INTEGER_8 = -129 -- E: VQMC(3)@23
	Over_16: INTEGER_16 = 32768 -- E: VQMC(3)
	Under_16: INTEGER_16 = -32769 -- E: VQMC(3)
	Over_32: INTEGER_32 = 2147483648 -- E: VQMC(3)
	Under_32: INTEGER = -2147483649 -- E: VQMC(3)
	Over_64: INTEGER_64 = 9223372036854775808 -- E: VQMC(3)
	Over_natural_8: NATURAL_8 = 0x100 -- E: VQMC(3)
	Over_natural_16: NATURAL_16 = 0c200000 -- E: VQMC(3)
	Over_natural_32: NATURAL_32 = 0b1_0000_0000_0000_0000_0000_0000_0000_0000 -- E: VQMC(3)
	Negative_natural: NATURAL_64 = -1 -- E: VQMC(3)

feature {NONE} -- Initialization

	make
			-- Print one of them.
		local
			x: INTEGER
		do
			x := 3000000000 -- E: VJAR
			print (Over_8)
		end

end
