note
	description: "Things that have a colour."

deferred class
	COLORED

inherit
	ANY
		redefine
			out
		end

feature -- Access

	color: STRING
			-- Colour name.
		deferred
		end

	name: STRING
			-- Name including the colour.
		do
			Result := color + " thing"
		end

	out: STRING
			-- Printable form.
		do
			Result := color
		end

end
