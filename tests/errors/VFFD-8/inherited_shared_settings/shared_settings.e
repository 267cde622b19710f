note
	description: "Access to the settings of the program."

class
	SHARED_SETTINGS

feature -- Access

	settings: SETTINGS -- E: VFFD(8)
			-- The settings, meant to be one object for the whole program.
		once ("PROCESS")
			create Result.make
		end

	shared_settings: separate SETTINGS
			-- The settings, one object for the whole program.
		once ("PROCESS")
			create Result.make
		end

end
