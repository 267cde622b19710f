note
	description: "RANDOM: EiffelStudio's Park-Miller sequence from the default seed and from chosen seeds."

class
	RANDOM_NUMBERS

create
	make

feature {NONE} -- Initialization

	make
		local
			r: RANDOM
			i: INTEGER
			dice: STRING
		do
			create r.make
			print ("seed " + r.seed.out + " index " + r.index.out + "%N")
			from
				i := 1
			until
				i > 5
			loop
				print (r.item.out + "%N")
				r.forth
				i := i + 1
			end
			print ("double_item " + r.double_item.out + "%N")
			print ("real_item " + r.real_item.out + "%N")
			print ("i_th (10) " + r.i_th (10).out + " i_th (1) " + r.i_th (1).out + "%N")
			print ("next_random (1) " + r.next_random (1).out + "%N")
			create r.set_seed (42)
			print ("set_seed 42: index " + r.index.out + " item " + r.item.out + "%N")
			r.forth
			print ("then " + r.item.out + "%N")
			r.start
			dice := ""
			from
				i := 1
			until
				i > 20
			loop
				dice.append_integer (r.item \\ 6 + 1)
				r.forth
				i := i + 1
			end
			print ("dice " + dice + "%N")
			print ("double_i_th (3) " + r.double_i_th (3).out + "%N")
		end

end
