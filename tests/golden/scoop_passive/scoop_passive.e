note
	description: "A passive region (`create <NONE>'): its clients run its calls themselves, one at a time."

class
	SCOOP_PASSIVE

create
	make

feature {NONE} -- Initialization

	make
		local
			t: separate TALLY
			c1, c2: separate CLICKER
		do
			create <NONE> t
			create c1.make (t, "c1")
			create c2.make (t, "c2")
			launch (c1)
			launch (c2)
			print ("tally " + final_value (t).out + "%N")
		end

feature {NONE} -- Implementation

	launch (c: separate CLICKER)
		do
			c.run
		end

	final_value (t: separate TALLY): INTEGER
		require
			all_clicks: t.value = 100
		do
			Result := t.value
		end

end
