note
	description: "Exceptions that come from the rules of the language: contracts, Void targets, failures."

deferred class
	LANGUAGE_EXCEPTION

inherit
	EXCEPTION

end
