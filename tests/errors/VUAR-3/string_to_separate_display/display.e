note
	description: "A small display on the robot."

class
	DISPLAY

create
	make

feature {NONE} -- Initialization

	make
			-- Blank display.
		do
			title := "status"
			create text.make_empty
		end

feature -- Access

	title: STRING
			-- Title shown at the top.

	text: STRING
			-- Text shown.

	brightness: INTEGER
			-- Backlight level in percent.

feature -- Element change

	show (a_text: STRING)
			-- Show `a_text'.
		do
			text := a_text
		end

	show_copy (a_text: separate STRING)
			-- Show a copy of `a_text'.
		do
			create text.make_from_separate (a_text)
		end

	set_brightness (a_level: INTEGER)
			-- Set the backlight to `a_level'.
		do
			brightness := a_level
		end

end
