note
	description: "[
		Misusing the library is a precondition violation, as in EiffelBase (ARRAY.item and put
		require `valid_index', SPECIAL and STRING guard their bounds, TUPLE creation gives one default item per
		type), never an exception of the host; ANY's features on basic values.
	]"

class
	LIBRARY_MISUSE

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			kind: INTEGER
			t: TUPLE [x: INTEGER; s: STRING; b: BOOLEAN]
			i: INTEGER
			n: NATURAL_8
			r: REAL_64
		do
			from kind := 1 until kind > 11 loop
				attempt (kind)
				kind := kind + 1
			end
			create t
			print ("created tuple: count " + t.count.out + ", x " + t.x.out + ", s is Void " + (t.s = Void).out + ", b " + t.b.out + "%N")
			i := 5
			print ("twin " + i.twin.out + ", is_equal " + i.is_equal (5).out + ", standard_is_equal " + i.standard_is_equal (6).out + "%N")
			n := 200
			r := 2.5
			print ("types " + i.generating_type.out + " " + n.generating_type.out + " " + r.generating_type.out + "%N")
			i.copy (7)
			print ("after copy " + i.out + "%N")
		end

feature {NONE} -- Implementation

	attempt (kind: INTEGER)
			-- Misuse number `kind', reporting the exception it raises.
		local
			failed: BOOLEAN
			a: ARRAY [INTEGER]
			s: SPECIAL [INTEGER]
			str: STRING
		do
			if not failed then
				create a.make_filled (0, 1, 3)
				create s.make_filled (0, 2)
				str := "abc"
				inspect kind
				when 1 then
					print (a.item (4))
				when 2 then
					print (a [0])
				when 3 then
					a.put (1, -1)
				when 4 then
					print (s.item (2))
				when 5 then
					print (s [-1])
				when 6 then
					s.put (1, 5)
				when 7 then
					s.extend (3)
				when 8 then
					s.keep_head (3)
				when 9 then
					str.put ('x', 0)
				when 10 then
					print (str.item (0))
				when 11 then
					str.insert_character ('x', 5)
				end
				print ("kind " + kind.out + ": no failure%N")
			end
		rescue
			if attached exception_manager.last_exception as e then
				print ("kind " + kind.out + ": " + e.original.generator + " " + e.original.tag + "%N")
			end
			failed := True
			retry
		end

end
