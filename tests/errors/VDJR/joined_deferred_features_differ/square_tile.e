deferred class
	SQUARE_TILE -- E: VDJR

inherit
	SHAPE

	TILE

end
