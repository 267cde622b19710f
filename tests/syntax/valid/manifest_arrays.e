note
	description: "Manifest arrays << >>, typed manifest arrays and empty ones."

class
	MANIFEST_ARRAYS

create
	make

feature {NONE} -- Initialization

	make
			-- Build arrays in place.
		local
			primes: ARRAY [INTEGER]
			names: ARRAY [STRING]
			mixed: ARRAY [ANY]
			matrix: ARRAY [ARRAY [INTEGER]]
			nothing: ARRAY [INTEGER]
			reals: ARRAY [REAL_64]
		do
			primes := <<2, 3, 5, 7, 11>>
			names := <<"ada", "bertrand", "edsger">>
			mixed := {ARRAY [ANY]} <<1, "two", 3.0, 'c'>>
			matrix := <<<<1, 0>>, <<0, 1>>>>
			nothing := <<>>
			reals := {ARRAY [REAL_64]} <<1.0, 2.5>>
			print (primes.count.out + " " + names [2] + " " + mixed.count.out + "%N")
			print (matrix [2] [2].out + " " + nothing.count.out + " " + reals [2].out + "%N")
			print (sum (<<1, 2, 3, 4>>).out + "%N")
			print (sum ({ARRAY [INTEGER]} <<>>).out + "%N")
			across << "x", "y" >> as c loop
				print (c.item)
			end
			print ("%N")
		end

feature -- Computation

	sum (a: ARRAY [INTEGER]): INTEGER
			-- Sum of the items of `a'.
		do
			across a as c loop
				Result := Result + c.item
			end
		end

end
