note
	description: "Static (non-object) calls {T}.f and class features."

class
	STATIC_CALLS

create
	make

feature {NONE} -- Initialization

	make
			-- Call features through types.
		local
			n: INTEGER_64
			x: REAL_64
		do
			n := {INTEGER_64}.max_value
			print (n.out + "%N")
			print ({INTEGER_32}.min_value.out + "%N")
			print ({NATURAL_8}.max_value.out + "%N")
			x := {MATH_CONST}.pi
			print (x.truncated_to_integer.out + "%N")
			print ({STATIC_CALLS}.double (21).out + "%N")
			print ({INTEGER_16}.max_value.out + "%N")
			print (({NATURAL_16}.max_value).out + "%N")
		end

feature -- Class features

	double (n: INTEGER): INTEGER
			-- Twice `n'; callable without an object.
		do
			Result := 2 * n
		ensure
			instance_free: class
			definition: Result = n + n
		end

end
