note
	description: "Tuples: types with and without labels, manifest tuples, field access and assignment."

class
	TUPLES_LABELS

create
	make

feature {NONE} -- Initialization

	make
			-- Build and take apart tuples.
		local
			pair: TUPLE [INTEGER, STRING]
			point: TUPLE [x, y: REAL_64]
			person: TUPLE [name: STRING; age: INTEGER; tags: ARRAY [STRING]]
			empty: TUPLE
			nested: TUPLE [inner: TUPLE [a, b: INTEGER]; label: STRING]
		do
			pair := [1, "one"]
			print (pair.integer_32_item (1).out + "%N")
			if attached {STRING} pair.item (2) as s then
				print (s + "%N")
			end
			point := [3.0, 4.0]
			point.x := 6.0
			print (((point.x ^ 2 + point.y ^ 2) ^ 0.5).out + "%N")
			person := ["Grace", 85, <<"admiral", "compiler">>]
			person.age := person.age + 1
			print (person.name + " " + person.age.out + " " + person.tags.count.out + "%N")
			empty := []
			print (empty.count.out + "%N")
			nested := [[1, 2], "pair"]
			print ((nested.inner.a + nested.inner.b).out + " " + nested.label + "%N")
			print (min_max (<<5, 3, 9, 1>>).min.out + "%N")
		end

feature -- Queries

	min_max (a: ARRAY [INTEGER]): TUPLE [min, max: INTEGER]
			-- The least and greatest items of `a'.
		require
			not_empty: not a.is_empty
		local
			lo, hi: INTEGER
		do
			lo := a [a.lower]
			hi := lo
			across a as c loop
				lo := lo.min (c.item)
				hi := hi.max (c.item)
			end
			Result := [lo, hi]
		ensure
			ordered: Result.min <= Result.max
		end

end
