note
	description: "Violated assertions (contracts, checks, loop invariants and variants)."

deferred class
	ASSERTION_VIOLATION

inherit
	LANGUAGE_EXCEPTION

end
