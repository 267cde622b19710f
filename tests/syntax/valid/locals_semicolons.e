note
	description: "Optional semicolons, argument and local lists, empty routines and compound instructions on one line."

class
	LOCALS_SEMICOLONS

create
	make

feature {NONE} -- Initialization

	make
			-- Declarations and instructions separated in every allowed way.
		local
			a, b, c: INTEGER; d: STRING
			e: BOOLEAN;
			f: REAL_64
		do
			a := 1; b := 2; c := 3
			d := "d";
			e := a < b; f := 1.5
			;
			print (combine (a, b, c, d).out + "%N");
			nothing_at_all
			nothing_with_comment;
			if e then print (f.out + "%N") end
			print (max3 (a, b, c).out + "%N")
			print (first_name + " " + given_name + " " + one_liner (1).out + "%N")
		end

feature -- Routines

	combine (x, y: INTEGER; z: INTEGER; s: STRING): INTEGER
			-- Mix of comma and semicolon separated arguments.
		do
			Result := x + y + z + s.count
		end

	max3 (x: INTEGER; y: INTEGER; z: INTEGER): INTEGER
			-- Largest of the three.
		do
			Result := x.max (y).max (z)
		end

	nothing_at_all do end

	nothing_with_comment
			-- A routine with an empty body.
		do
			-- Nothing to do.
		end;

	one_liner (n: INTEGER): INTEGER do Result := n + 1 end

	first_name, given_name: STRING
			-- Two names for one routine (synonyms).
		do
			Result := "Bertrand"
		end

end
