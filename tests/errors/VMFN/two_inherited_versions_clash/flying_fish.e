class
	FLYING_FISH -- E: VMFN

inherit
	BIRD

	FISH

end
