note
	description: "Language exceptions specific to EiffelStudio's implementation."

deferred class
	EIFFELSTUDIO_SPECIFIC_LANGUAGE_EXCEPTION

inherit
	LANGUAGE_EXCEPTION

end
