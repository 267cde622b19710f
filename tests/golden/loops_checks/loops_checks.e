note
	description: "Loops with invariant and variant, check instructions, debug instructions (off by default)."

class
	LOOPS_CHECKS

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			i, sum: INTEGER
			s: detachable STRING
		do
			from
				i := 1
				sum := 0
			invariant
				in_range: i >= 1 and i <= 11
				partial_sum: sum = (i - 1) * i // 2
			until
				i > 10
			loop
				sum := sum + i
				i := i + 1
			variant
				11 - i
			end
			print ("sum " + sum.out + "%N")
			check
				expected_sum: sum = 55
			end
			s := "checked"
			check attached s as t then
				print (t + "%N")
			end
			debug
				print ("debug output is off%N")
			end
			debug ("trace")
				print ("keyed debug output is off%N")
			end
			print ("gcd " + gcd (1071, 462).out + "%N")
			print (guarded ("variant") + "%N")
			print (guarded ("invariant") + "%N")
			print (guarded ("check") + "%N")
		end

feature {NONE} -- Implementation

	gcd (a, b: INTEGER): INTEGER
		local
			x, y, t: INTEGER
		do
			from
				x := a
				y := b
			invariant
				x > 0 and y >= 0
			until
				y = 0
			loop
				t := x \\ y
				x := y
				y := t
			variant
				y
			end
			Result := x
		end

	guarded (what: STRING): STRING
		local
			failed: BOOLEAN
		do
			if failed then
				Result := what + " violation caught"
			elseif what ~ "variant" then
				bad_variant
				Result := "no violation"
			elseif what ~ "invariant" then
				bad_invariant
				Result := "no violation"
			else
				check
					false_check: what.is_empty
				end
				Result := "no violation"
			end
		rescue
			if attached exception_manager.last_exception as e then
				print (e.generator + " " + e.tag + ": ")
			end
			failed := True
			retry
		end

	bad_variant
		local
			i: INTEGER
		do
			from
				i := 0
			until
				i = 3
			loop
				i := i + 1
			variant
				non_decreasing: i
			end
		end

	bad_invariant
		local
			i: INTEGER
		do
			from
				i := 0
			invariant
				small: i < 2
			until
				i = 5
			loop
				i := i + 1
			end
		end

end
