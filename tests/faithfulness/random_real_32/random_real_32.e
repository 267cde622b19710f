class
	RANDOM_REAL_32

create
	make

feature

	make
			-- `real_item` is a REAL_32 (ISE: item / modulus in single precision); scaled and
			-- floored as EiffelStudio's quicksort example does.
		local
			r: RANDOM
			x: REAL
			i: INTEGER
		do
			create r.set_seed (14)
			from
				r.start
				i := 1
			until
				i > N
			loop
				if i > N - 3 then
					x := r.real_item
					print ((x * 1000).floor.out + "%N")
				end
				r.forth
				i := i + 1
			end
		end

	N: INTEGER = 755

end
