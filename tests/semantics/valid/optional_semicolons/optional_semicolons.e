note
	description: "Semicolons wherever ECMA-367 allows one, and none where it allows none.";
	status: "test"
class
	OPTIONAL_SEMICOLONS
inherit
	ANY
		redefine
			out
		end;
	DEBUG_OUTPUT
		export
			{NONE} all;
		end
create
	make
feature {NONE} -- Initialization

	make
			-- Semicolons before, between and after instructions; labelled tuples.
		local
			l_count: INTEGER; l_name: STRING;
			l_point: TUPLE [x, y: INTEGER; name: STRING];
			l_pair: TUPLE [key: INTEGER value: STRING]
		do
			;
			l_count := sum (1, "two");;
			l_name := "x"; if l_count = 1 then ; print (l_name); end;
			l_point := [1, 2, "p"]; print (l_point.name)
			l_pair := [l_count, l_point.name]
			print (l_pair.value);
		ensure
			True;
		end;

feature -- Access

	out: STRING
		do
			Result := "s"
		end;

	debug_output: STRING do Result := "d" end

	sum (a: INTEGER; b: STRING;): INTEGER
			-- A trailing semicolon after the last argument group.
		do
			Result := a + b.count
		end

	product (a: INTEGER b: INTEGER): INTEGER
			-- No semicolon between argument groups.
		do
			Result := a * b
		end

end
