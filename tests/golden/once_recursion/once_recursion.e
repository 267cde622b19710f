note
	description: "[
		A call of a once routine during its own first execution returns the value its Result
		has so far (ECMA-367 8.23.22; EiffelStudio keeps a once function's Result in the once's
		own data): per thread (the default), per process and per object; a once procedure's
		recursive call does nothing.
	]"

class
	ONCE_RECURSION

create
	make

feature {NONE} -- Initialization

	make
		local
			n1, n2: NODE
		do
			print ("default: " + counter.out + "%N")
			print ("default again: " + counter.out + "%N")
			print ("before any assignment: " + fresh.out + "%N")
			print ("process: " + shared_code.out + "%N")
			print ("process again: " + shared_code.out + "%N")
			create n1.make (10)
			create n2.make (20)
			print ("object: " + n1.total.out + " " + n2.total.out + " " + n1.total.out + "%N")
			setup
			setup
			print ("setup ran " + setups.out + " time(s)%N")
		end

feature -- Onces

	counter: INTEGER
			-- 1, then a recursive call seeing 1, then 3.
		once
			Result := 1
			print ("counter: recursive call sees " + counter.out + "%N")
			Result := Result + counter + 1
		end

	fresh: INTEGER
			-- A recursive call in the first assignment sees the default 0.
		once
			Result := counter + fresh + 100
		end

	shared_code: INTEGER
			-- 7, then 70 + what a recursive call sees (7).
		once ("PROCESS")
			Result := 7
			Result := Result * 10 + shared_code
		end

	setups: INTEGER

	setup
			-- A once procedure: its recursive call does nothing.
		once
			setups := setups + 1
			print ("setup: " + setups.out + "%N")
			setup
			print ("setup: after the recursive call%N")
		end

end
