class
	SHARED_ACCOUNT

inherit
	BASE_ACCOUNT
		export
			{EXPORT_ALL} owner
			{STRING} owner
		end

end
