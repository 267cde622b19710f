note
	description: "Access to the exception manager; inherit it or create it to reach `exception_manager'."

class
	EXCEPTION_MANAGER_FACTORY

feature -- Access

	exception_manager: EXCEPTION_MANAGER
			-- The exception manager (one per processor).
		once
			create Result
		end

end
