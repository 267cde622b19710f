class
	RUNNER [G -> separate WORKABLE]

feature -- Basic operations

	run (w: G; n: INTEGER)
			-- `w' is a separate argument (its type's constraint is separate): reserved here.
		do
			w.work (n)
		end

	total (w: G): INTEGER
		do
			Result := w.done
		end

	run_all (ws: ITERABLE [G]; n: INTEGER)
		do
			across ws is w loop
				run (w, n)
			end
		end

end
