note
	description: "Loops: from/until/loop with invariant and variant, and across with as/is, all/some."

class
	LOOPS_ACROSS

create
	make

feature {NONE} -- Initialization

	make
			-- Run each kind of loop over a small list.
		local
			numbers: ARRAYED_LIST [INTEGER]
			i, sum: INTEGER
			words: ARRAY [STRING]
		do
			create numbers.make (10)
			from
				i := 1
			invariant
				count_matches: numbers.count = i - 1
			until
				i > 10
			loop
				numbers.extend (i * i)
				i := i + 1
			variant
				remaining: 11 - i
			end
				-- across with a cursor: `c.item' is the element.
			across numbers as c loop
				sum := sum + c.item
			end
			print (sum.out + "%N")
				-- across with an item name.
			sum := 0
			across numbers is n loop
				sum := sum + n
			end
			print (sum.out + "%N")
				-- Quantifiers.
			print ((across numbers as c all c.item > 0 end).out + "%N")
			print ((across numbers as c some c.item \\ 7 = 0 end).out + "%N")
			print ((across numbers is n all n >= 1 end and across numbers is n some n = 100 end).out + "%N")
				-- Integer intervals.
			across 1 |..| 5 as k loop
				print (k.item.out + " ")
			end
			print ("%N")
				-- The general form: across with from, invariant, until, variant.
			across numbers as c from
				sum := 0
			invariant
				non_negative: sum >= 0
			until
				sum > 50
			loop
				sum := sum + c.item
			variant
				50 - sum + 1000
			end
			print (sum.out + "%N")
				-- Nested loops, and a loop with an empty body.
			words := <<"alpha", "beta", "gamma">>
			across words as w loop
				across w.item as ch loop
					if ch.item = 'a' then
						print (ch.item)
					end
				end
			end
			print ("%N")
			from i := 0 until i >= 3 loop i := i + 1 end
			from
			until
				True
			loop
			end
			print (i.out + "%N")
				-- A cursor's position.
			across words as w loop
				print (w.cursor_index.out + ":" + w.item + " ")
			end
			print ("%N")
		end

end
