note
	description: "Operator aliases of user classes: binary, unary, free operators, `[]' with an assigner, COMPARABLE."

class USER_OPERATORS
create make
feature
	make
		local
			a, b, c: VEC
			m: MATRIX
			r: RATIONAL
		do
			create a.make (1, 2)
			create b.make (3, 4)
			c := a + b
			print (c.out + " " + (-a).out + " " + (a |*| 3).out + " " + (a * b).out + " " + (a < b).out + " " + (b.max (a)).out + "%N")
			create m.make (2)
			m [1, 2] := 5
			m.put (7, 2, 1)
			print (m [1, 2].out + " " + m.item (2, 1).out + " " + m [2, 2].out + "%N")
			create r.make (1, 3)
			r := r + create {RATIONAL}.make (1, 6)
			print (r.out + " " + (r ~ create {RATIONAL}.make (1, 2)).out + "%N")
		end
end
