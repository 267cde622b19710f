note
	description: "Mathematical functions on REAL_64 values; inherit it or create it."
	implementation: "Every function is `external %"Python%"' (Python's math module)."

class
	DOUBLE_MATH

inherit
	MATH_CONST

feature -- Access

	cosine (v: REAL_64): REAL_64
			-- Cosine of `v' (radians).
		external
			"Python"
		end

	sine (v: REAL_64): REAL_64
			-- Sine of `v' (radians).
		external
			"Python"
		end

	tangent (v: REAL_64): REAL_64
			-- Tangent of `v' (radians).
		external
			"Python"
		end

	arc_cosine (v: REAL_64): REAL_64
			-- Angle in 0..Pi whose cosine is `v'.
		require
			in_range: v >= -1.0 and v <= 1.0
		external
			"Python"
		end

	arc_sine (v: REAL_64): REAL_64
			-- Angle in -Pi/2..Pi/2 whose sine is `v'.
		require
			in_range: v >= -1.0 and v <= 1.0
		external
			"Python"
		end

	arc_tangent (v: REAL_64): REAL_64
			-- Angle in -Pi/2..Pi/2 whose tangent is `v'.
		external
			"Python"
		end

	sqrt (v: REAL_64): REAL_64
			-- Square root of `v'.
		require
			non_negative: v >= 0.0
		external
			"Python"
		end

	exp (x: REAL_64): REAL_64
			-- e raised to the power `x'.
		external
			"Python"
		end

	log (v: REAL_64): REAL_64
			-- Natural logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	log_2 (v: REAL_64): REAL_64
			-- Base-2 logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	log10 (v: REAL_64): REAL_64
			-- Base-10 logarithm of `v'.
		require
			positive: v > 0.0
		external
			"Python"
		end

	floor (v: REAL_64): REAL_64
			-- Greatest integral value no greater than `v'.
		external
			"Python"
		end

	ceiling (v: REAL_64): REAL_64
			-- Smallest integral value no smaller than `v'.
		external
			"Python"
		end

	dabs (v: REAL_64): REAL_64
			-- Absolute value of `v'.
		do
			Result := v.abs
		end

end
