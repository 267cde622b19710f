expanded class
	VECTOR

inherit
	ANY
		redefine
			out
		end

feature -- Access

	x, y: INTEGER

	out: STRING
		do
			Result := "<" + x.out + "," + y.out + ">"
		end

feature -- Change

	set (ax, ay: INTEGER)
		do
			x := ax
			y := ay
		end

	scale (f: INTEGER)
		do
			x := x * f
			y := y * f
		end

end
