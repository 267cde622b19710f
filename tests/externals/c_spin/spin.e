note
	description: "The root processor inside a C external that does not return (Ctrl-C must still end the program)."

class
	SPIN

create
	make

feature

	make
		do
			spin
		end

	spin external "C blocking inline use <stdio.h>, <unistd.h>" alias "fprintf (stderr, %"spinning\n%"); fflush (stderr); for (int i = 0; i < 600; i++) usleep (100000);" end

end
