note
	description: "[
		Reservations whose body only calls the reserved supplier's short routines (which the
		client runs itself when it can): commands and queries in order, a failed command makes
		the next query raise the dirty processor exception, a failed query raises at once, a
		command failing after the last query is lost; a passive region and a separate reference
		into the client's own region keep their own rules (failures reach the client as they are).
	]"

class
	SCOOP_DIRECT_BLOCKS

create
	make

feature {NONE} -- Initialization

	make
		local
			c, p, own: separate ACCUMULATOR
			mine: ACCUMULATOR
		do
			create c
			print ("sum " + add_twice (c, 3).out + "%N")
			print (failed_command (c) + "%N")
			print ("clean again: " + add_twice (c, 1).out + "%N")
			print (failed_query (c) + "%N")
			print ("last " + query_then_failing_command (c).out + "%N")
			print ("after the loss: " + add_twice (c, 2).out + "%N")
			stored := 0
			copy_total (c)
			print ("stored " + stored.out + "%N")
			print ("waited for " + total_when_over (c, 10).out + "%N")
			create <NONE> p
			print ("passive sum " + add_twice (p, 5).out + "%N")
			print (failed_command (p) + "%N")
			create mine
			own := mine
			print ("own sum " + add_twice (own, 4).out + "%N")
			print (failed_command (own) + "%N")
		end

feature {NONE} -- Implementation

	add_twice (a: separate ACCUMULATOR; n: INTEGER): INTEGER
			-- Two commands, then a query.
		do
			a.add (n)
			a.add (n)
			Result := a.total
		end

	failed_command (a: separate ACCUMULATOR): STRING
			-- A command fails; the query after it tells.
		local
			tried: BOOLEAN
		do
			if tried then
				Result := "failed: " + exception_text
			else
				Result := "not reached " + add_then_total (a, -1).out
			end
		rescue
			tried := True
			retry
		end

	add_then_total (a: separate ACCUMULATOR; n: INTEGER): INTEGER
			-- `n' then 1 added, the total.
		do
			a.add (n)
			a.add (1)
			Result := a.total
		end

	failed_query (a: separate ACCUMULATOR): STRING
			-- A query fails: the client gets its failure.
		local
			tried: BOOLEAN
		do
			if tried then
				Result := "the query failed: " + exception_text
			else
				Result := "not reached " + add_then_checked (a).out
			end
		rescue
			tried := True
			retry
		end

	add_then_checked (a: separate ACCUMULATOR): INTEGER
			-- 1 added, then the checked total.
		do
			a.add (1)
			Result := a.checked_total (0)
		end

	query_then_failing_command (a: separate ACCUMULATOR): INTEGER
			-- The command after the last query fails once the client has gone on: lost.
		do
			Result := a.total
			a.add (-1)
		end

	copy_total (a: separate ACCUMULATOR)
			-- A query's result goes to an attribute of Current.
		do
			a.add (0)
			stored := a.total
		end

	total_when_over (a: separate ACCUMULATOR; n: INTEGER): INTEGER
			-- A wait condition, then the body.
		require
			over: a.total > n
		do
			a.add (n)
			Result := a.total
		end

	exception_text: STRING
			-- What the last exception was, in short.
		do
			if attached (create {EXCEPTION_MANAGER}).last_exception as e then
				Result := e.generating_type.name.to_string_8
				if attached e.description as d then
					Result := Result + " (" + d.to_string_8 + ")"
				end
			else
				Result := "none"
			end
		end

	stored: INTEGER
			-- Where `copy_total' puts the total.

end
