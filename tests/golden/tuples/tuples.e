note
	description: "TUPLE: manifest tuples, labels, item/put, conformance, tuples as results."

class
	TUPLES

create
	make

feature {NONE} -- Initialization

	make
		local
			person: TUPLE [name: STRING; age: INTEGER]
			pair, other: TUPLE [INTEGER, INTEGER]
			short: TUPLE [INTEGER]
			d: like divmod
		do
			person := ["Ann", 30]
			show ("labels", person.name + " " + person.age.out + " count " + person.count.out)
			person.age := person.age + 1
			person.name := "Anna"
			show ("label assigners", person.name + " " + person.age.out)
			person.put ("Bob", 1)
			person [2] := 40
			if attached {STRING} person.item (1) as s and attached {INTEGER} person [2] as n then
				show ("item, put", s + " " + n.out)
			end
			show ("integer_item", person.integer_item (2).out + " " + person.is_integer_item (2).out + " " + person.is_integer_item (1).out)
			pair := [1, 2]
			other := [1, 2]
			show ("equality", (pair = other).out + " " + (pair ~ other).out + " " + pair.is_equal (other).out)
			other.put (3, 2)
			show ("after put", (pair ~ other).out + " " + other.integer_item (2).out)
			short := [7, "extra", True]
			show ("conformance", short.count.out + " " + short.integer_item (1).out)
			d := divmod (17, 5)
			show ("result tuple", d.quotient.out + " " + d.remainder.out)
			show ("nested", nested.integer_item (1).out)
			if attached {TUPLE [x: INTEGER; y: INTEGER]} pair as p then
				show ("object test", (p.x + p.y).out)
			end
		end

feature {NONE} -- Implementation

	divmod (a, b: INTEGER): TUPLE [quotient, remainder: INTEGER]
		do
			Result := [a // b, a \\ b]
		end

	nested: TUPLE [INTEGER, TUPLE [STRING]]
		do
			Result := [1, ["inner"]]
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
