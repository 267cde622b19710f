note
	description: "A fixed-size vector of reals with bracket access, an assigner and free operators."

class
	VECTOR

create
	make

feature {NONE} -- Initialization

	make (n: INTEGER)
			-- Create a zero vector of dimension `n'.
		require
			n_positive: n > 0
		do
			create values.make_filled (0.0, 1, n)
		ensure
			dimension_set: dimension = n
		end

feature -- Access

	dimension: INTEGER
			-- Number of components.
		do
			Result := values.count
		end

	item alias "[]" alias "@" (i: INTEGER): REAL_64 assign put
			-- The `i'-th component.
		require
			valid_index: 1 <= i and i <= dimension
		do
			Result := values [i]
		end

feature -- Element change

	put (v: REAL_64; i: INTEGER)
			-- Set the `i'-th component to `v'.
		require
			valid_index: 1 <= i and i <= dimension
		do
			values [i] := v
		ensure
			set: item (i) = v
		end

feature -- Operations

	dot alias "|*|" (other: VECTOR): REAL_64
			-- Scalar product.
		require
			same_dimension: other.dimension = dimension
		local
			i: INTEGER
		do
			from
				i := 1
			until
				i > dimension
			loop
				Result := Result + Current [i] * other [i]
				i := i + 1
			end
		end

	norm alias "#": REAL_64
			-- Euclidean length (a free unary operator).
		do
			Result := (Current |*| Current) ^ 0.5
		end

feature {VECTOR} -- Implementation

	values: ARRAY [REAL_64]
			-- The components.

invariant
	values_exist: values /= Void

end
