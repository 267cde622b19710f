note
	description: "Remembered positions in a structure, for returning to them later with `go_to'."

deferred class
	CURSOR

end
