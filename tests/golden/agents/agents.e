note
	description: "Agents: open and closed operands, open targets, inline agents, agents as arguments, calls."

class
	AGENTS

create
	make

feature {NONE} -- Initialization

	make
		local
			f: FUNCTION [INTEGER, INTEGER, INTEGER]
			g: FUNCTION [INTEGER, INTEGER]
			h: FUNCTION [STRING, INTEGER]
			p: PROCEDURE [STRING]
			q: PROCEDURE
			even: PREDICATE [INTEGER]
			n: INTEGER
			list: ARRAYED_LIST [INTEGER]
			total: INTEGER
		do
			f := agent add
			show ("item", f.item ([2, 3]).out + " " + f (4, 5).out + " open_count " + f.open_count.out)
			f.call ([10, 20])
			show ("last_result", f.last_result.out)
			g := agent add (10, ?)
			show ("closed first", g (5).out)
			g := agent add (?, 100)
			show ("closed second", g (5).out)
			n := 1
			g := agent add (n, ?)
			n := 100
			show ("closed at creation", g (1).out)
			h := agent {STRING}.count
			show ("open target", h ("abcd").out + " " + h.item (["xy"]).out)
			p := agent say
			p.call (["hi"])
			p ("there")
			q := agent bump
			q.call (Void)
			q.call ([])
			show ("counter", counter.out)
			even := agent (x: INTEGER): BOOLEAN do Result := x \\ 2 = 0 end
			show ("predicate", even (4).out + " " + even (7).out)
			show ("as argument", twice (agent double, 3).out + " " + twice (agent (x: INTEGER): INTEGER do Result := x + counter end, 1).out)
			create list.make (5)
			list.extend (3)
			list.extend (8)
			list.extend (6)
			list.do_all (agent (x: INTEGER) do print (x.out + " ") end)
			print ("%N")
			list.do_all (agent accumulate (?, 2))
			show ("accumulated", accumulated.out)
			list.do_if (agent say_integer, even)
			print ("%N")
			show ("for_all even", list.for_all (even).out)
			show ("there_exists even", list.there_exists (even).out)
			across list is x loop
				total := total + (agent double).item ([x])
			end
			show ("total", total.out)
			show ("inline with closed", (agent (a, b: INTEGER): INTEGER do Result := a * b end (6, ?)).item ([7]).out)
			show ("attribute agent", (agent counter).item ([]).out)
		end

feature {NONE} -- Implementation

	counter: INTEGER

	accumulated: INTEGER

	add (a, b: INTEGER): INTEGER
		do
			Result := a + b
		end

	double (x: INTEGER): INTEGER
		do
			Result := 2 * x
		end

	twice (fn: FUNCTION [INTEGER, INTEGER]; x: INTEGER): INTEGER
		do
			Result := fn (fn (x))
		end

	say (s: STRING)
		do
			print ("say: " + s + "%N")
		end

	say_integer (i: INTEGER)
		do
			print (i.out + " is even ")
		end

	bump
		do
			counter := counter + 1
		end

	accumulate (x, factor: INTEGER)
		do
			accumulated := accumulated + x * factor
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
