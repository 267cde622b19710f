note
	description: "A weather station keeping its samples."

class
	STATION

create
	make

feature {NONE} -- Initialization

	make
			-- Station with one sample.
		do
			create values.make (10)
			values.extend (25)
		end

feature -- Access

	latest: SAMPLE
			-- The latest sample.
		do
			Result.set ("station", values.last)
		end

	latest_value: INTEGER
			-- Value of the latest sample.
		do
			Result := values.last
		end

feature {NONE} -- Implementation

	values: ARRAYED_LIST [INTEGER]
			-- Values measured so far.

end
