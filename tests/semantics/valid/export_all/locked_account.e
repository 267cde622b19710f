class
	LOCKED_ACCOUNT

inherit
	BASE_ACCOUNT
		export
			{EXPORT_ALL} balance
			{NONE} all
		end

end
