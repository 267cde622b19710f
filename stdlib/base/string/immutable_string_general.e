note
	description: "Strings whose characters never change once created; safe to share between objects."

deferred class
	IMMUTABLE_STRING_GENERAL

inherit
	READABLE_STRING_GENERAL
		redefine
			is_immutable
		end

feature -- Status report

	is_immutable: BOOLEAN
			-- Can the characters of the string never change? (Yes.)
		do
			Result := True
		end

end
