note
	description: "Objects that have a hash code, so that they can be keys of hash tables."

deferred class
	HASHABLE

feature -- Access

	hash_code: INTEGER_32
			-- Hash code value; equal objects have equal hash codes.
		deferred
		ensure
			good_hash_value: Result >= 0
		end

feature -- Status report

	is_hashable: BOOLEAN
			-- May the current object be hashed?
		do
			Result := True
		end

end
