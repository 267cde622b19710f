indexing -- E: SYNTAX-OBSOLETE@1
	description: "A class from old course notes."

class
	OLD_NOTES

end
