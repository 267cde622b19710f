note
	description: "Shows status messages on a separate display."

class
	DASHBOARD

create
	make

feature {NONE} -- Initialization

	make
			-- Create a display and update it.
		local
			l_display: separate DISPLAY
			l_text: STRING
		do
			create l_display.make
			l_text := "battery ok"
			update (l_display, l_text)
		end

feature -- Basic operations

	update (a_display: separate DISPLAY; a_text: STRING)
			-- Show `a_text' on `a_display'.
		do
			a_display.show ("ready") -- E: VUAR(3)
			a_display.show (a_text) -- E: VUAR(3)
			a_display.show_copy (a_text)
			a_display.show_copy ("ready")
			a_display.show (a_display.title) -- E: VUAR(2)
			a_display.set_brightness (80)
		end

end
