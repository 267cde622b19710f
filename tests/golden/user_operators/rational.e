class RATIONAL
inherit ANY redefine out, is_equal end
create make
feature
	num, den: INTEGER
	make (n, d: INTEGER) local g: INTEGER do g := gcd (n.abs, d.abs); num := n // g; den := d // g end
	gcd (a, b: INTEGER): INTEGER do if b = 0 then Result := a else Result := gcd (b, a \\ b) end end
	plus alias "+" (o: RATIONAL): RATIONAL do create Result.make (num * o.den + o.num * den, den * o.den) end
	is_equal (o: like Current): BOOLEAN do Result := num = o.num and den = o.den end
	out: STRING do Result := num.out + "/" + den.out end
end
