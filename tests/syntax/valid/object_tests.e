note
	description: "Object tests and attachment marks: attached {T} e as x, detachable, Void checks."

class
	OBJECT_TESTS

create
	make

feature {NONE} -- Initialization

	make
			-- Classify a few values by their dynamic type.
		local
			items: ARRAYED_LIST [detachable ANY]
		do
			create items.make (5)
			items.extend ("text")
			items.extend (42)
			items.extend (Void)
			items.extend (3.5)
			items.extend (create {ARRAYED_LIST [INTEGER]}.make (0))
			across items as c loop
				print (describe (c.item) + "%N")
			end
			last_name := "Ada"
			if attached last_name as n and then not n.is_empty then
				print (n + "%N")
			end
			if not attached find ("nobody") then
				print ("not found%N")
			end
			if attached find ("Ada") as found then
				print (found.count.out + "%N")
			end
			check attached last_name as n2 then
				print (n2.as_upper + "%N")
			end
		end

feature -- Access

	last_name: detachable STRING
			-- The most recent name, if any.

	describe (x: detachable ANY): STRING
			-- A description of `x' by its type.
		do
			if attached {STRING} x as s then
				Result := "string of " + s.count.out
			elseif attached {INTEGER} x as i and then i > 0 then
				Result := "positive integer " + i.out
			elseif attached {REAL_64} x as r then
				Result := "real " + r.out
			elseif attached {LIST [INTEGER]} x as l then
				Result := "list of " + l.count.out
			elseif x = Void then
				Result := "void"
			else
				Result := "something else"
			end
		ensure
			not_empty: not Result.is_empty
		end

	find (name: STRING): detachable STRING
			-- `name' if it is the last name.
		do
			if attached last_name as l and then l ~ name then
				Result := l
			end
		end

	checked_length (s: detachable STRING): INTEGER
			-- Length of `s', or -1.
		do
			Result := -1
			if attached s then
				Result := s.count
			end
		end

	attached_twice (a, b: detachable ANY): BOOLEAN
			-- Are both `a' and `b' attached to strings of one length?
		do
			Result := attached {STRING} a as sa and then attached {STRING} b as sb and then sa.count = sb.count
		end

	forced (a: detachable STRING): attached STRING
			-- `a' or a default.
		do
			if attached a then
				Result := a
			else
				Result := "default"
			end
		end

end
