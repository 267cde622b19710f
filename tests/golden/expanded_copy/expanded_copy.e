note
	description: "[
		Copy semantics of expanded values (ECMA-367 8.21; EiffelStudio reattaches an expanded value
		with `twin', which calls the redefined `copy'): assignment, argument passing, a function's
		result, manifest tuples and arrays, agent operands and `twin' make copies with `copy', and
		the copy is not shared with the source; `standard_copy' and `standard_is_equal' work on the
		fields of the argument itself.
	]"

class
	EXPANDED_COPY

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: TALLY
			t: TUPLE [item: TALLY]
			items: ARRAY [TALLY]
			f: FUNCTION [TALLY]
		do
			a.set (1)
			print ("source: " + a.out + "%N")
			b := a
			a.set (2)
			print ("assignment: " + b.out + "%N")
			show (a)
			print ("after the call: " + a.out + "%N")
			b := made (3)
			print ("result: " + b.out + "%N")
			t := [a]
			a.set (4)
			print ("tuple item: " + t.item.out + "%N")
			items := <<a>>
			a.set (5)
			print ("array item: " + items [1].out + "%N")
			f := agent same_tally (a)
			a.set (6)
			print ("agent operand: " + f.item ([]).out + "%N")
			b := a.twin
			a.set (7)
			print ("twin: " + b.out + "%N")
			b.standard_copy (a)
			print ("standard_copy: " + b.out + "%N")
			b.set (8)
			b.copy (a)
			print ("copy: " + b.out + "%N")
			print ("standard_is_equal: " + b.standard_is_equal (a).out + ", is_equal: " + b.is_equal (a).out + ", =: " + (b = a).out + "%N")
			b.standard_copy (a)
			print ("after standard_copy, standard_is_equal: " + b.standard_is_equal (a).out + "%N")
		end

feature {NONE} -- Implementation

	show (x: TALLY)
		do
			print ("argument: " + x.out + "%N")
			x.set (100)
		end

	made (v: INTEGER): TALLY
		do
			Result.set (v)
		end

	same_tally (x: TALLY): TALLY
		do
			Result := x
		end

end
