note
	description: "[
		The root of every class: comparison, duplication, output and the few
		operations every object has. A class without an inherit clause inherits ANY.
	]"
	implementation: "[
		Features marked `external "built_in"' are provided by the code generator
		(reflection, copying, comparison). `print' and `io' are plain Eiffel:
		`print' writes `out' of its argument through `io.put_string', one call at a time.
	]"

class
	ANY

feature -- Access

	generator: STRING_8
			-- Name of the class of which the current object is a direct instance.
		external
			"built_in"
		end

	generating_type: TYPE [detachable like Current]
			-- Type of which the current object is a direct instance.
		external
			"built_in"
		end

feature -- Status report

	conforms_to (other: ANY): BOOLEAN
			-- Does the dynamic type of the current object conform to the dynamic type of `other'?
		external
			"built_in"
		end

	same_type (other: ANY): BOOLEAN
			-- Do the current object and `other' have the same dynamic type?
		external
			"built_in"
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Is `other' considered equal to the current object?
			-- By default: same type and the same field values (`standard_is_equal').
		do
			Result := standard_is_equal (other)
		end

	frozen standard_is_equal (other: like Current): BOOLEAN
			-- Are the current object and `other' of the same type, with identical fields?
		external
			"built_in"
		end

	frozen equal (a: detachable ANY; b: like a): BOOLEAN
			-- Are `a' and `b' both Void, or attached to objects that are `is_equal'?
		do
			if a = Void then
				Result := b = Void
			elseif b /= Void then
				Result := a.is_equal (b)
			end
		end

	frozen standard_equal (a: detachable ANY; b: like a): BOOLEAN
			-- Are `a' and `b' both Void, or attached to objects that are `standard_is_equal'?
		do
			if a = Void then
				Result := b = Void
			elseif b /= Void then
				Result := a.standard_is_equal (b)
			end
		end

	frozen is_deep_equal (other: like Current): BOOLEAN
			-- Are the object structures reachable from the current object and from `other' isomorphic?
		external
			"built_in"
		end

	frozen deep_equal (a: detachable ANY; b: like a): BOOLEAN
			-- Are `a' and `b' both Void, or attached to isomorphic object structures?
		do
			if a = Void then
				Result := b = Void
			elseif b /= Void then
				Result := a.is_deep_equal (b)
			end
		end

feature -- Duplication

	frozen twin: like Current
			-- New object equal to the current one, made by `copy'.
		external
			"built_in"
		end

	copy (other: like Current)
			-- Make the current object's fields equal to those of `other'.
			-- Redefine this (never `twin') to change how objects of a class are duplicated.
		require
			type_identity: same_type (other)
		external
			"built_in"
		end

	frozen standard_copy (other: like Current)
			-- Copy every field of `other' onto the current object.
		require
			type_identity: same_type (other)
		external
			"built_in"
		end

	frozen standard_twin: like Current
			-- New object whose fields are identical to the current object's.
		external
			"built_in"
		end

	frozen deep_twin: like Current
			-- New object structure, recursively duplicated from the current object.
		external
			"built_in"
		end

	frozen deep_copy (other: like Current)
			-- Make the current object a deep copy of `other'.
		do
			copy (other.deep_twin)
		end

feature -- Output

	io: STD_FILES
			-- Standard input, output and error.
		once
			create Result
			Result.set_output_default
		end

	out: STRING_8
			-- Short printable representation of the current object.
		do
			Result := tagged_out
		end

	frozen tagged_out: STRING_8
			-- Printable representation of the current object: its class name and fields.
		external
			"built_in"
		end

	print (o: detachable ANY)
			-- Write `o.out' on the standard output, if `o' is attached.
			-- (A separate object is printed through a copy: `print (create {STRING}.make_from_separate (x.out))'.)
		do
			if attached o as l_o then
				io.put_string (l_o.out)
			end
		end

feature -- Platform

	Operating_environment: OPERATING_ENVIRONMENT
			-- Properties of the operating system.
		once
			create Result
		end

feature {NONE} -- Initialization

	default_create
			-- Initialize a new object; the creation procedure of classes that list none.
		do
		end

feature -- Basic operations

	default_rescue
			-- Handle an exception in a routine that has no rescue clause (default: nothing).
		do
		end

	frozen do_nothing
			-- Do nothing.
		do
		end

	frozen default: detachable like Current
			-- Default value of the current object's type.
		do
		end

	frozen default_pointer: POINTER
			-- The null pointer.
		do
		end

end
