note
	description: "An obsolete class with obsolete features, kept for old clients."
	status: "deprecated"

class
	OLD_LOGGER

obsolete
	"Use NEW_LOGGER instead. [2025-01-01]"

feature -- Logging

	write (s: STRING)
			-- Print `s'.
		obsolete
			"Call `log' instead. [2025-01-01]"
		do
			log (s)
		end

	log (s: STRING)
			-- Print `s' with a prefix.
		do
			print ("[log] " + s + "%N")
		end

	level: INTEGER
		obsolete "Levels are gone."
		attribute
			Result := 1
		end

end
