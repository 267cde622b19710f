note
	description: "BOOLEAN operators, strict and semi-strict, and their output."

class
	BOOLEAN_OPS

create
	make

feature {NONE} -- Initialization

	make
		local
			t, f: BOOLEAN
		do
			t := True
			show ("default", f.out)
			show ("and", (t and f).out + " " + (t and t).out)
			show ("or", (t or f).out + " " + (f or f).out)
			show ("xor", (t xor t).out + " " + (t xor f).out + " " + (f xor f).out)
			show ("implies", (f implies t).out + " " + (t implies f).out + " " + (f implies f).out + " " + (t implies t).out)
			show ("not", (not t).out + " " + (not f).out)
			show ("precedence", (not f and f).out + " " + (t or t and f).out + " " + (f implies f and t).out)
			if f and then touched then
				show ("unreachable", "")
			end
			if t or else touched then
				show ("or else", "right operand skipped")
			end
			if f implies touched then
				show ("implies", "right operand skipped")
			end
			if t and then touched then
				show ("unreachable", "")
			end
			show ("touches", touches.out)
			show ("equality", (t = True).out + " " + (t /= f).out)
			show ("to_integer", t.to_integer.out + " " + f.to_integer.out)
			show ("hash_code", t.hash_code.out)
			print (t)
			print ("%N")
			io.put_boolean (f)
			io.put_new_line
		end

feature {NONE} -- Implementation

	touches: INTEGER

	touched: BOOLEAN
			-- Count the evaluations; False.
		do
			touches := touches + 1
		end

	show (label: STRING; value: STRING)
		do
			print (label + ": " + value + "%N")
		end

end
