note
	description: "Evaluates a query of a sensor on its own processor."

class
	PROBE

create
	evaluate, evaluate_any

feature {NONE} -- Initialization

	evaluate (a_query: separate FUNCTION [ANY])
			-- Evaluate `a_query' once.
		do
			a_query.call
			count := 1
		end

	evaluate_any (a_query: separate FUNCTION [detachable separate ANY])
			-- Evaluate `a_query' once; its result may live anywhere.
		do
			a_query.call
			count := 1
		end

feature -- Access

	count: INTEGER
			-- Number of evaluations made.

end
