class
	HOLDER

feature

	content: ?STRING -- E: SYNTAX-OBSOLETE@11

end
