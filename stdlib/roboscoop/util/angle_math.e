note
	description: "Angle helpers (radians): normalization, differences, conversions, atan2."

class
	ANGLE_MATH

inherit
	DOUBLE_MATH

feature -- Access

	arc_tangent_2 (y, x: REAL_64): REAL_64
			-- Angle of the vector (`x', `y'), in [-pi, pi].
		external
			"Python"
		end

	normalized_angle (a: REAL_64): REAL_64
			-- `a' brought into (-pi, pi].
		do
			Result := a
			from until Result <= Pi loop
				Result := Result - 2.0 * Pi
			end
			from until Result > -Pi loop
				Result := Result + 2.0 * Pi
			end
		ensure
			in_range: -Pi < Result and Result <= Pi
		end

	angle_difference (a, b: REAL_64): REAL_64
			-- Signed smallest rotation from `b' to `a', in (-pi, pi].
		do
			Result := normalized_angle (a - b)
		end

	degrees (a_radians: REAL_64): REAL_64
			-- `a_radians' in degrees.
		do
			Result := a_radians * 180.0 / Pi
		end

	radians (a_degrees: REAL_64): REAL_64
			-- `a_degrees' in radians.
		do
			Result := a_degrees * Pi / 180.0
		end

end
