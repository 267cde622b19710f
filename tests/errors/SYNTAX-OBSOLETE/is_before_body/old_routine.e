class
	OLD_ROUTINE

feature

	double (x: INTEGER): INTEGER is -- E: SYNTAX-OBSOLETE@31
		do
			Result := 2 * x
		end

end
