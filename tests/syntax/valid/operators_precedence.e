note
	description: "[
		Every Eiffel operator, with and without parentheses, so the tree shows
		precedence and associativity: ^ is right-associative, the others left.
		]"

class
	OPERATORS_PRECEDENCE

create
	make

feature {NONE} -- Initialization

	make
			-- Evaluate expressions whose grouping depends on precedence.
		local
			a, b, c: INTEGER
			x: REAL_64
			p, q, r: BOOLEAN
			s, t: STRING
		do
			a := 7
			b := 3
			c := 2
				-- Arithmetic.
			print ((a + b * c).out + "%N")
			print (((a + b) * c).out + "%N")
			print ((a - b - c).out + "%N")
			print ((a - (b - c)).out + "%N")
			print ((a // b).out + " " + (a \\ b).out + "%N")
			print ((a // b * b + a \\ b).out + "%N")
			print ((-a // b).out + " " + (-a \\ b).out + "%N")
			x := a / b
			print (x.out + "%N")
			x := 2 ^ 3 ^ 2
			print (x.out + "%N")
			x := (2 ^ 3) ^ 2
			print (x.out + "%N")
			x := -2 ^ 2
			print (x.out + "%N")
			print ((- a + + b).out + "%N")
			print ((a * -b).out + "%N")
				-- Comparison.
			p := a + 1 > b * 2
			q := a = b or a /= c
			r := a <= b and b >= c or a < c
			print (p.out + " " + q.out + " " + r.out + "%N")
				-- Boolean operators, loosest last: and/and then, or/or else/xor, implies.
			p := True
			q := False
			r := p or q and r
			print (r.out + "%N")
			r := not p or q
			print (r.out + "%N")
			r := not (p or q)
			print (r.out + "%N")
			r := p and then q or else not q
			print (r.out + "%N")
			r := p xor q xor r
			print (r.out + "%N")
			r := p implies q implies r
			print (r.out + "%N")
			r := (p implies q) implies r
			print (r.out + "%N")
			r := p implies q or r and not p
			print (r.out + "%N")
			r := a > 0 and then b // a > 0 or else c = 0
			print (r.out + "%N")
				-- Object and reference equality.
			s := "abc"
			t := "ab" + "c"
			print ((s ~ t).out + " " + (s /~ t).out + "%N")
			print ((s = t).out + " " + (s /= t).out + "%N")
			print ((s ~ t and s /= t).out + "%N")
				-- Intervals.
			print ((1 |..| 10).count.out + "%N")
			print ((a - 5 |..| a + 5).upper.out + "%N")
				-- Calls bind tighter than every operator.
			print ((a.max (b) + b.min (c) * a.abs).out + "%N")
			print ((s.count + t.count * 2).out + "%N")
			print ((-s.count).out + "%N")
			print ((old_style (a) + 1).out + "%N")
		end

feature -- Helpers

	old_style (n: INTEGER): INTEGER
			-- `n' squared: a name that starts with a keyword is still a name.
		do
			Result := n * n
		ensure
			definition: Result = n ^ 2
		end

end
