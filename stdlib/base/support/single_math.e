note
	description: "Mathematical functions on REAL_32 values; inherit it or create it."
	implementation: "Every function is `external %"Python%"' (Python's math module)."

class
	SINGLE_MATH

inherit
	MATH_CONST

feature -- Access

	cosine (v: REAL_32): REAL_32
			-- Cosine of `v' (radians).
		external
			"Python"
		end

	sine (v: REAL_32): REAL_32
			-- Sine of `v' (radians).
		external
			"Python"
		end

	tangent (v: REAL_32): REAL_32
			-- Tangent of `v' (radians).
		external
			"Python"
		end

	arc_cosine (v: REAL_32): REAL_32
			-- Angle in 0..Pi whose cosine is `v'.
		require
			in_range: v >= -1.0 and v <= 1.0
		external
			"Python"
		end

	arc_sine (v: REAL_32): REAL_32
			-- Angle in -Pi/2..Pi/2 whose sine is `v'.
		require
			in_range: v >= -1.0 and v <= 1.0
		external
			"Python"
		end

	arc_tangent (v: REAL_32): REAL_32
			-- Angle in -Pi/2..Pi/2 whose tangent is `v'.
		external
			"Python"
		end

	sqrt (v: REAL_32): REAL_32
			-- Square root of `v'.
		require
			non_negative: v >= 0.0
		external
			"Python"
		end

	exp (x: REAL_32): REAL_32
			-- e raised to the power `x'.
		external
			"Python"
		end

	log (v: REAL_32): REAL_32
			-- Natural logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	log_2 (v: REAL_32): REAL_32
			-- Base-2 logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	log10 (v: REAL_32): REAL_32
			-- Base-10 logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	floor (v: REAL_32): REAL_32
			-- Greatest integral value no greater than `v'.
		external
			"Python"
		end

	ceiling (v: REAL_32): REAL_32
			-- Smallest integral value no smaller than `v'.
		external
			"Python"
		end

	rabs (v: REAL_32): REAL_32
			-- Absolute value of `v'.
		do
			Result := v.abs
		end

end
