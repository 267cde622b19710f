note
	description: "Agents on named routines: unqualified, qualified, open and closed operands, open targets."

class
	AGENTS_ROUTINES

create
	make

feature {NONE} -- Initialization

	make
			-- Build agents of every kind and call them.
		local
			action: PROCEDURE [STRING]
			two_args: PROCEDURE [INTEGER, INTEGER]
			no_args: PROCEDURE
			doubler: FUNCTION [INTEGER, INTEGER]
			measure: FUNCTION [STRING, INTEGER]
			test: PREDICATE [INTEGER]
			list: ARRAYED_LIST [INTEGER]
			text: STRING
		do
			action := agent say
			action.call (["hello"])
			action ("direct call")
			two_args := agent add_to_total
			two_args.call ([2, 3])
			no_args := agent add_to_total (10, 20)
			no_args.call (Void)
			no_args.call ([])
			two_args := agent add_to_total (?, ?)
			two_args (1, 1)
			action := agent add_label ("n", ?)
			action.call (["x"])
			doubler := agent double
			print (doubler.item ([21]).out + "%N")
			print (doubler (4).out + "%N")
			text := "agents"
			measure := agent {STRING}.count
			print (measure.item ([text]).out + "%N")
			no_args := agent text.append ("!")
			no_args.call (Void)
			print (text + "%N")
			action := agent text.append (?)
			action.call ([" again"])
			action := agent {STRING}.to_upper
			action.call ([text])
			print (text + "%N")
			test := agent is_even
			print (test.item ([4]).out + "%N")
			test := agent Current.is_even (?)
			print (test (3).out + "%N")
			create list.make (5)
			list.extend (3)
			list.extend (4)
			list.do_all (agent show_number)
			print (list.for_all (agent is_even).out + "%N")
			print (list.there_exists (agent is_even).out + "%N")
			list.do_if (agent show_number, agent is_even)
			print (total.out + "%N")
			print ((agent double).item ([5]).out + "%N")
			if attached doubler.last_result as r then
				print (r.out + "%N")
			end
		end

feature -- Access

	total: INTEGER
			-- Sum of everything added.

feature -- Routines used as agents

	say (s: STRING)
			-- Print `s'.
		do
			print (s + "%N")
		end

	add_to_total (a, b: INTEGER)
			-- Add `a' and `b' to `total'.
		do
			total := total + a + b
		end

	add_label (label, value: STRING)
			-- Print `label' = `value'.
		do
			print (label + " = " + value + "%N")
		end

	double (n: INTEGER): INTEGER
			-- Twice `n'.
		do
			Result := n * 2
		end

	is_even (n: INTEGER): BOOLEAN
			-- Is `n' even?
		do
			Result := n \\ 2 = 0
		end

	show_number (n: INTEGER)
			-- Print `n'.
		do
			print (n.out + "%N")
		end

end
