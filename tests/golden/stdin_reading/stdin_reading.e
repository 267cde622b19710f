note
	description: "Reading standard input: read_line, read_integer, read_double, read_word, end of input."

class
	STDIN_READING

create
	make

feature {NONE} -- Initialization

	make
		local
			name: STRING
			total, n, count: INTEGER
		do
			io.read_line
			name := io.last_string.twin
			print ("hello " + name + "%N")
			io.read_integer
			n := io.last_integer
			print ("first number " + n.out + "%N")
			io.read_double
			print ("a double " + io.last_double.out + "%N")
			io.read_word
			print ("a word [" + io.last_string + "]%N")
			io.read_line
			print ("rest of line [" + io.last_string + "]%N")
			from
				io.read_line
			until
				io.input.end_of_file
			loop
				if io.last_string.is_integer then
					total := total + io.last_string.to_integer
					count := count + 1
				else
					print ("skipped [" + io.last_string + "]%N")
				end
				io.read_line
			end
			print ("sum of " + count.out + " lines: " + total.out + "%N")
		end

end
