note
	description: "A visitor adding up coordinates."

class
	SUM_VISITOR

inherit
	VISITOR
		redefine
			finish
		end

feature -- Visiting

	visit (p: POINT)
			-- <Precursor>
		do
			sum := sum + p.x + p.y
		end

	finish
			-- <Precursor>
		do
			Precursor
			finished := True
		end

	result_text: STRING
			-- <Precursor>
		do
			Result := sum.out
			if finished then
				Result := Result + " (finished)"
			end
		end

feature -- Access

	sum: INTEGER
	finished: BOOLEAN

end
