note
	description: "Properties of the operating system, as ANY.Operating_environment gives them."

class
	OPERATING_ENVIRONMENT

feature -- Access

	directory_separator: CHARACTER_8
			-- Character separating the parts of a path ('/' or '\').
		external
			"Python"
		end

	current_directory_name_representation: STRING_8
			-- Name of the current directory in paths (".").
		do
			Result := "."
		end

feature -- Status report

	home_directory_supported: BOOLEAN = True
			-- Do users have a home directory? (Yes.)

	root_directory_supported: BOOLEAN = True
			-- Does the file system have a root directory? (Yes.)

	case_sensitive_path_names: BOOLEAN
			-- Do the names of files depend on case?
		external
			"Python"
		end

end
