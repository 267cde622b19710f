note
	description: "print and io.put_* of every basic type, strings, Void; io.error goes to stderr."

class
	PRINTING

create
	make

feature {NONE} -- Initialization

	make
		local
			i8: INTEGER_8
			i16: INTEGER_16
			i64: INTEGER_64
			n8: NATURAL_8
			n16: NATURAL_16
			n32: NATURAL_32
			n64: NATURAL_64
			r: REAL_32
			d: REAL_64
			c32: CHARACTER_32
			nothing: detachable ANY
		do
			i8 := -128
			i16 := 32767
			i64 := {INTEGER_64}.min_value
			n8 := 255
			n16 := 65535
			n32 := 4294967295
			n64 := {NATURAL_64}.max_value
			r := 0.1
			d := 0.1
			c32 := 'Z'
			print (42)
			print (" ")
			print (-7)
			print (" ")
			print (i8)
			print (" ")
			print (i16)
			print (" ")
			print (i64)
			print ("%N")
			print (n8)
			print (" ")
			print (n16)
			print (" ")
			print (n32)
			print (" ")
			print (n64)
			print ("%N")
			print (r)
			print (" ")
			print (d)
			print (" ")
			print (2.5)
			print (" ")
			print (100.0)
			print ("%N")
			print (True)
			print (" ")
			print ('c')
			print (" ")
			print (c32)
			print (" ")
			print (nothing)
			print ("[")
			print (nothing)
			print ("]%N")
			io.put_string ("put_string")
			io.put_new_line
			io.put_integer (-5)
			io.put_character (' ')
			io.put_integer_8 (i8)
			io.put_character (' ')
			io.put_integer_16 (i16)
			io.put_character (' ')
			io.put_integer_64 (i64)
			io.put_new_line
			io.put_natural_8 (n8)
			io.put_character (' ')
			io.put_natural_16 (n16)
			io.put_character (' ')
			io.put_natural (n32)
			io.put_character (' ')
			io.put_natural_64 (n64)
			io.put_new_line
			io.put_real (r)
			io.put_character (' ')
			io.put_double (d)
			io.put_character (' ')
			io.put_real (1.0e10)
			io.put_character (' ')
			io.put_double (1.0e10)
			io.put_new_line
			io.put_boolean (False)
			io.put_character (' ')
			io.put_character ('x')
			io.put_new_line
			io.output.put_string ("via output%N")
			io.error.put_string ("to stderr%N")
			io.put_string ("last line without newline")
		end

end
