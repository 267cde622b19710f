class
	LENGTH

inherit
	ANY
		redefine
			out
		end

create
	make_centimetres

feature {NONE} -- Initialization

	make_centimetres (n: INTEGER)
		require
			not_negative: n >= 0
		do
			centimetres := n
		end

feature -- Access

	centimetres: INTEGER

	plus alias "+" (other: LENGTH): LENGTH
		do
			create Result.make_centimetres (centimetres + other.centimetres)
		end

	out: STRING
		do
			Result := (centimetres // 100).out + " m " + (centimetres \\ 100).out + " cm"
		end

end
