class VEC
inherit
	COMPARABLE
		redefine out end
create make
feature
	x, y: INTEGER
	make (ax, ay: INTEGER) do x := ax; y := ay end
	plus alias "+" (o: like Current): like Current do create Result.make (x + o.x, y + o.y) end
	opposite alias "-": like Current do create Result.make (-x, -y) end
	scaled alias "|*|" (k: INTEGER): like Current do create Result.make (k * x, k * y) end
	dot alias "*" (o: like Current): INTEGER do Result := x * o.x + y * o.y end
	is_less alias "<" (o: like Current): BOOLEAN do Result := x * x + y * y < o.x * o.x + o.y * o.y end
	out: STRING do Result := "(" + x.out + "," + y.out + ")" end
end
