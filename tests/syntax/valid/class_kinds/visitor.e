note
	description: "A deferred class with a deferred routine, an effective routine calling it, and a deferred query."

deferred class
	VISITOR

feature -- Visiting

	visit (p: POINT)
			-- Handle `p'.
		deferred
		end

	visit_all (points: ITERABLE [POINT])
			-- Handle each point.
		do
			across points as c loop
				visit (c.item)
			end
			finish
		end

	finish
			-- Called after the last point.
		do
		end

	result_text: STRING
			-- What the visit found.
		deferred
		end

end
