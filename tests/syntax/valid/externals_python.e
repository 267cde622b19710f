note
	description: "External routines bound to Python callables, with and without alias."

class
	EXTERNALS_PYTHON

create
	make

feature {NONE} -- Initialization

	make
			-- Call Python through externals.
		do
			print (square_root (2.0).out + "%N")
			print (cosine (0.0).out + "%N")
			print (maximum (3, 9).out + "%N")
			log_message ("external call done")
		end

feature -- Externals

	square_root (x: REAL_64): REAL_64
			-- Square root, computed by Python's math module.
		require
			non_negative: x >= 0.0
		external
			"Python"
		alias
			"math.sqrt"
		ensure
			non_negative: Result >= 0.0
		end

	cosine (x: REAL_64): REAL_64
			-- Cosine of `x' (radians).
		external "Python" alias "math.cos"
		end

	maximum (a, b: INTEGER): INTEGER
			-- The larger of `a' and `b', by Python's max.
		external
			"Python"
		alias
			"builtins.max"
		end

	log_message (message: STRING)
			-- Write `message' with Python's logging.
		external
			"Python"
		end

end
