indexing
	description: "A class in the syntax of EiffelStudio 6: every form the transitional level accepts"

class
	OLD_STYLE

create
	make

feature -- Initialization

	make is
			-- Show each old form at work.
		local
			a: ANY
		do
			a := "text"
			if {s: STRING} a then
				print ("a string of " + s.count.out + " characters%N")
			end
			print ("found: " + found.out + ", limit: " + Limit.out + "%N")
			label := "set"
			if attached label as l then
				print (l + "%N")
			end
		end

feature -- Access

	label: ?STRING

	name: !STRING is
			-- A name.
		do
			Result := "old"
		end

	found: BOOLEAN is
		do
			Result := label = Void
		end

	Limit: INTEGER is 10

end
