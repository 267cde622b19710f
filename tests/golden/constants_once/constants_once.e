note
	description: "Constant attributes of every basic type and once routines (functions, procedures, per object)."

class
	CONSTANTS_ONCE

create
	make

feature {NONE} -- Initialization

	make
		local
			r1, r2: REGISTRY
		do
			print (Max.out + " " + Big.out + " " + Small.out + " " + Ratio.out + " " + Letter.out + " " + Flag.out + " " + Greeting + "%N")
			print (Hex.out + " " + Negative.out + " " + Tiny.out + "%N")
			print ("first id: " + next_id.out + ", again: " + next_id.out + ", evaluated " + evaluations.out + " time(s)%N")
			setup
			setup
			print ("setup ran " + setups.out + " time(s)%N")
			create r1
			create r2
			r1.shared_list.extend ("one")
			r2.shared_list.extend ("two")
			r1.own_list.extend ("mine")
			print ("shared: " + r1.shared_list.count.out + " " + (r1.shared_list = r2.shared_list).out + "%N")
			print ("per object: " + r1.own_list.count.out + " " + r2.own_list.count.out + " " + (r1.own_list = r2.own_list).out + "%N")
			print ("failing once: " + guarded_once.out + " " + guarded_once.out + "%N")
			print ("unique: " + Red.out + " " + Green.out + " " + Blue.out + "%N")
		end

feature {NONE} -- Constants

	Max: INTEGER = 10
	Big: INTEGER_64 = 5_000_000_000
	Small: NATURAL_8 = 255
	Ratio: REAL_64 = 0.25
	Letter: CHARACTER = 'x'
	Flag: BOOLEAN = True
	Greeting: STRING = "hello"
	Hex: INTEGER = 0x1F
	Negative: INTEGER = -7
	Tiny: REAL_32 = 0.5
	Red, Green: INTEGER = unique
			-- Distinct values, numbered in the order the class declares them.
	Blue: INTEGER = unique

feature {NONE} -- Once routines

	evaluations: INTEGER

	setups: INTEGER

	next_id: INTEGER
		once
			evaluations := evaluations + 1
			Result := 42
		end

	setup
		once
			setups := setups + 1
		end

	attempts: INTEGER

	failing: INTEGER
			-- Raises on its first (and only) evaluation: every later call raises again.
		once
			attempts := attempts + 1
			check
				never: False
			end
			Result := 1
		end

	guarded_once: STRING
		local
			failed: BOOLEAN
		do
			if failed then
				Result := "raised (evaluations " + attempts.out + ")"
			else
				Result := failing.out
			end
		rescue
			failed := True
			retry
		end

end
