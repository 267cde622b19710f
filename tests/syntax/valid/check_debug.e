note
	description: "The check instruction (plain and with then), and debug (plain and with keys)."

class
	CHECK_DEBUG

create
	make

feature {NONE} -- Initialization

	make
			-- Make assertions along the way.
		local
			n: INTEGER
			name: detachable STRING
		do
			n := 10
			check
				positive: n > 0
				even: n \\ 2 = 0
			end
			check n < 100 end
			check
			end
			name := "scoop"
			check attached name as s then
				print (s.count.out + "%N")
			end
			check has_name: attached name as s2 then
				print (s2 + "%N")
			end
			debug
				print ("debugging%N")
			end
			debug ("trace")
				print ("tracing n = " + n.out + "%N")
			end
			debug ("trace", "verbose")
				print ("very verbose%N")
			end
			check
				has_name: name /= Void
				-- A comment among the assertions.
				long_enough: attached name as s3 implies s3.count >= 1
			end
			print ("done%N")
		end

end
