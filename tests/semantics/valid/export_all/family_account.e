class
	FAMILY_ACCOUNT

inherit
	SHARED_ACCOUNT

end
