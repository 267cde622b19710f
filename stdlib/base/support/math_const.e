note
	description: "Mathematical constants."

class
	MATH_CONST

feature -- Access

	Pi: REAL_64 = 3.1415926535897932384626433832795029
			-- Ratio of a circle's circumference to its diameter.

	Pi_2: REAL_64 = 1.5707963267948966192313216916397514
			-- Pi / 2.

	Pi_4: REAL_64 = 0.7853981633974483096156608458198757
			-- Pi / 4.

	One_over_pi: REAL_64 = 0.3183098861837906715377675267450287
			-- 1 / Pi.

	Two_over_pi: REAL_64 = 0.6366197723675813430755350534900574
			-- 2 / Pi.

	Two_over_sqrt_pi: REAL_64 = 1.1283791670955125738961589031215452
			-- 2 / sqrt (Pi).

	Sqrt2: REAL_64 = 1.4142135623730950488016887242096981
			-- Square root of 2.

	Sqrt1_2: REAL_64 = 0.7071067811865475244008443621048490
			-- Square root of 1/2.

	Euler: REAL_64 = 2.7182818284590452353602874713526625
			-- Base of the natural logarithm (e).

end
