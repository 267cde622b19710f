note
	description: "A rover reading the settings shared by the program."

class
	ROVER

inherit
	SHARED_SETTINGS

create
	make

feature {NONE} -- Initialization

	make
			-- Print the speed limit.
		do
			print (settings.max_speed)
			show (shared_settings)
		end

feature -- Basic operations

	show (a_settings: separate SETTINGS)
			-- Print the speed limit in `a_settings'.
		do
			print (a_settings.max_speed)
		end

end
