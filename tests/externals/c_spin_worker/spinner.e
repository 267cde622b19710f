class
	SPINNER

feature

	spin: INTEGER
		external "C blocking inline use <stdio.h>, <unistd.h>"
		alias "fprintf (stderr, %"spinning\n%"); fflush (stderr); for (int i = 0; i < 600; i++) usleep (100000); return 1;"
		end

end
