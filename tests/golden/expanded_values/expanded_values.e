note
	description: "Expanded values are copied on assignment, argument passing and retrieval from containers."

class
	EXPANDED_VALUES

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: VECTOR
			p: PARTICLE
			list: ARRAYED_LIST [VECTOR]
			i, j: INTEGER
		do
			print ("default: " + a.out + "%N")
			a.set (1, 2)
			b := a
			b.set (10, 20)
			print ("assignment copies: " + a.out + " " + b.out + "%N")
			print ("equality: " + (a = b).out + " " + (a = a).out)
			b.set (1, 2)
			print (" " + (a = b).out + " " + (a ~ b).out + "%N")
			create p
			p.move (a)
			p.move (a)
			print ("argument copies: " + p.position.out + " " + a.out + "%N")
			create list.make (2)
			list.extend (a)
			a.scale (5)
			print ("container copies: " + list.first.out + " " + a.out + "%N")
			b := list.first
			b.scale (3)
			print ("retrieval copies: " + list.first.out + " " + b.out + "%N")
			i := 5
			j := i
			j := j + 1
			print ("integers: " + i.out + " " + j.out + "%N")
		end

end
