note
	description: "Inline agents: with arguments, results, locals, contracts and closed operands."

class
	AGENTS_INLINE

create
	make

feature {NONE} -- Initialization

	make
			-- Use inline agents with EiffelBase iteration.
		local
			numbers: ARRAYED_LIST [INTEGER]
			square: FUNCTION [INTEGER, INTEGER]
			greet: PROCEDURE
			add: FUNCTION [INTEGER, INTEGER, INTEGER]
			sum: CELL [INTEGER]
			prefix_: STRING
		do
			create numbers.make (4)
			numbers.extend (1)
			numbers.extend (2)
			numbers.extend (3)
			square := agent (n: INTEGER): INTEGER
				do
					Result := n * n
				ensure
					non_negative: Result >= 0
				end
			print (square.item ([7]).out + "%N")
			greet := agent
				do
					print ("hello from an inline agent%N")
				end
			greet.call (Void)
			add := agent (a, b: INTEGER): INTEGER do Result := a + b end
			print (add (2, 3).out + "%N")
			create sum.put (0)
			numbers.do_all (agent (n: INTEGER; s: CELL [INTEGER])
				require
					positive: n > 0
				local
					before: INTEGER
				do
					before := s.item
					s.put (before + n)
				end (?, sum))
			print (sum.item.out + "%N")
			print (numbers.for_all (agent (n: INTEGER): BOOLEAN do Result := n < 10 end).out + "%N")
			print (numbers.there_exists (agent (n: INTEGER): BOOLEAN
				do
					Result := n = 2
				end).out + "%N")
			prefix_ := "item "
			numbers.do_all (agent (n: INTEGER; p: STRING) do print (p + n.out + "%N") end (?, prefix_))
			;(agent (s: STRING) do print (s) end).call (["called directly%N"])
			print ((agent: INTEGER do Result := 42 end).item (Void).out + "%N")
			print (compose (square, agent (n: INTEGER): INTEGER do Result := n + 1 end).item ([3]).out + "%N")
		end

feature -- Combinators

	compose (f, g: FUNCTION [INTEGER, INTEGER]): FUNCTION [INTEGER, INTEGER]
			-- The function applying `g' then `f'.
		do
			Result := agent (x: INTEGER; ff, gg: FUNCTION [INTEGER, INTEGER]): INTEGER
				do
					Result := ff.item ([gg.item ([x])])
				end (?, f, g)
		end

end
