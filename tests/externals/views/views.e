note
	description: "[
		ARRAY and SPECIAL of numbers reach a Python external as numpy views of their items: what
		the external writes is in the Eiffel structure, and no copy is made (the view owns no data).
		An external that keeps a view past the call leaves the SPECIAL free to grow: it goes on with
		a copy of its own, and later writes through the kept view do not reach it.
	]"

class
	VIEWS

create
	make

feature

	make
		local
			a: ARRAY [REAL_64]
			s: SPECIAL [INTEGER_64]
			b: SPECIAL [INTEGER_8]
			r: ARRAY [REAL_32]
		do
			create a.make_filled (1.5, 1, 4)
			double (a)
			double (a)
			print ("doubled twice: " + a [1].out + " " + a [4].out + ", a view: " + is_view (a).out + "%N")
			print ("copies: " + (a.twin ~ a).out + " " + a.deep_twin.is_deep_equal (a).out + " "
				+ a.area.standard_is_equal (a.area.twin).out + " " + (a.area.twin.item (3) = 6.0).out + "%N")
			create s.make_empty (4)
			s.extend (7)
			s.extend (7)
			s.extend (7)
			keep (s)
			s.extend (9)
			s.put (8, 0)
			write_kept
			print ("kept view: count " + s.count.out + ", items " + s [0].out + " " + s [1].out + " " + s [3].out + "%N")
			create b.make_filled (-128, 2)
			negate_bytes (b)
			print ("bytes: " + b [0].out + " " + b [1].out + "%N")
			create r.make_filled ({REAL_32} 0.5, 1, 2)
			add_third (r)
			print ("reals: " + r [1].out + " " + r.count.out + "%N")
		end

feature -- Externals

	double (a: ARRAY [REAL_64]) external "Python" alias "views_mod.double" end
	is_view (a: ARRAY [REAL_64]): BOOLEAN external "Python" alias "views_mod.is_view" end
	keep (s: SPECIAL [INTEGER_64]) external "Python" alias "views_mod.keep" end
	write_kept external "Python" alias "views_mod.write_kept" end
	negate_bytes (b: SPECIAL [INTEGER_8]) external "Python" alias "views_mod.negate_bytes" end
	add_third (r: ARRAY [REAL_32]) external "Python" alias "views_mod.add_third" end

end
