note
	description: "Agents standing for a call to a function returning a BOOLEAN: tests and conditions."

class
	PREDICATE [OPEN_ARGS -> detachable TUPLE create default_create end]

inherit
	FUNCTION [OPEN_ARGS, BOOLEAN]

create {NONE}

end
