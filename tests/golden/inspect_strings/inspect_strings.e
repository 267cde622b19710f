note
	description: "inspect on strings compares their characters, not their identity: strings built at %
		%run time match manifest and constant choices, in the instruction and in the expression."

class
	INSPECT_STRINGS

create
	make

feature {NONE} -- Initialization

	make
		local
			words: ARRAY [STRING]
			s: STRING
			w: STRING_32
		do
			words := <<"one", "many", "none", "zero">>
			across words as c loop
				create s.make_from_string (c.item)
				print (s + ": " + kind (s) + ", " + size (s) + "%N")
			end
			s := "ma"
			s.append ("ny")
			print (kind (s) + "%N")
			create w.make_from_string ({STRING_32} "été")
			inspect w
			when "été" then
				print ("summer%N")
			else
				print ("not summer%N")
			end
		end

feature {NONE} -- Implementation

	Many: STRING = "many"

	kind (s: STRING): STRING
		do
			inspect s
			when "one" then
				Result := "single"
			when Many then
				Result := "several"
			when "zero", "none" then
				Result := "nothing"
			else
				Result := "unknown"
			end
		end

	size (s: STRING): STRING
		do
			Result := inspect s when "one" then "1" when "many" then "n" else "0" end
		end

end
