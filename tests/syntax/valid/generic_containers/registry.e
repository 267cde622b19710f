note
	description: "A table with several generic constraints, a creation constraint and a renaming constraint."

class
	REGISTRY [K -> {HASHABLE, COMPARABLE}, V -> ANY create default_create end, N -> NUMERIC rename zero as numeric_zero end]

create
	make

feature {NONE} -- Initialization

	make
			-- Create an empty registry.
		do
			create table.make (8)
			create fresh
		end

feature -- Access

	table: HASH_TABLE [V, K]
			-- Entries by key.

	fresh: V
			-- A value made by `V's default creation procedure.

	weight: detachable N
			-- An optional numeric weight.

	value_for (k: K): V
			-- The value for `k', created on first use.
		do
			if attached table.item (k) as v then
				Result := v
			else
				create Result
				table.put (Result, k)
			end
		end

	smallest_key: detachable K
			-- The least key, if any.
		do
			across table.current_keys as c loop
				if attached Result as r implies c.item < r then
					Result := c.item
				end
			end
		end

	nested: detachable ARRAYED_LIST [TUPLE [key: K; values: LIST [V]]]
			-- A type with nested actual generics.

end
