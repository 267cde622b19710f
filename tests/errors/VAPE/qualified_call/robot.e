class
	ROBOT

feature {ARM} -- Status

	is_calibrated: BOOLEAN
			-- Only ARM may ask.

end
