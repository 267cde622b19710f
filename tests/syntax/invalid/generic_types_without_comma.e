class
	GENERIC_TYPES_WITHOUT_COMMA

feature

	table: detachable HASH_TABLE [STRING INTEGER] -- E: SYNTAX

end
