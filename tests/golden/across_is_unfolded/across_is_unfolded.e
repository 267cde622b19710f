note
	description: "[
		`across s is x' and `⟳ x: s ¦ ... ⟲' behave as their unfolded form, a loop over
		`s.new_cursor' where each `x' is the cursor's `item' where it is read: a body that changes
		the current item sees the change, in all three forms.
	]"

class
	ACROSS_IS_UNFOLDED

create
	make

feature {NONE} -- Initialization

	make
		local
			a: ARRAY [INTEGER]
			c: ITERATION_CURSOR [INTEGER]
			i: INTEGER
		do
			a := <<1, 2>>
			across a is x loop
				i := i + 1
				print (x.out + " ")
				a [i] := x * 10
				print (x.out + " ")
			end
			print ("(across is)%N")
			a := <<1, 2>>
			i := 0
			⟳ x: a ¦ i := i + 1; print (x.out + " "); a [i] := x * 10; print (x.out + " ") ⟲
			print ("(symbolic)%N")
			a := <<1, 2>>
			i := 0
			from
				c := a.new_cursor
			until
				c.after
			loop
				i := i + 1
				print (c.item.out + " ")
				a [i] := c.item * 10
				print (c.item.out + " ")
				c.forth
			end
			print ("(unfolded)%N")
		end

end
