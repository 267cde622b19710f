class
	OPEN_ACCOUNT

inherit
	LOCKED_ACCOUNT
		export
			{ANY} all
		end

end
