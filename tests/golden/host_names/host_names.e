note
	description: "Eiffel names that are Python keywords, builtins or names of the generated code."

class
	HOST_NAMES

create
	make

feature {NONE} -- Initialization

	make
		local
			list, str, sum, len, type, object, range, int, s, b, t, k, rt, ks, here, self, dict: INTEGER
			id, next, iter, open, format, input, min, max, abs, hash, super: STRING
		do
			list := 1
			str := 2
			sum := 3
			len := 4
			type := 5
			object := 6
			range := 7
			int := 8
			s := 9
			b := 10
			t := 11
			k := 12
			rt := 13
			ks := 14
			here := 15
			self := 16
			dict := 17
			print ((list + str + sum + len + type + object + range + int + s + b + t + k + rt + ks + here + self + dict).out + "%N")
			id := "id"
			next := "next"
			iter := "iter"
			open := "open"
			format := "format"
			input := "input"
			min := "min"
			max := "max"
			abs := "abs"
			hash := "hash"
			super := "super"
			print (id + next + iter + open + format + input + min + max + abs + hash + super + "%N")
			pass
			lambda (2)
			print (yield.out + " " + global.out + " " + del (3).out + " " + try.out + " " + with.out + " " + import + " " + def + "%N")
			print (None_of_these + " " + object_count.out + "%N")
		end

feature -- Python keywords as feature names

	pass
		do
			print ("pass%N")
		end

	lambda (x: INTEGER)
		do
			print ("lambda " + x.out + "%N")
		end

	yield: INTEGER = 1

	global: BOOLEAN = True

	del (x: INTEGER): INTEGER
		do
			Result := x * 2
		end

	try: CHARACTER = 't'

	with: REAL_64 = 2.5

	import: STRING = "import"

	def: STRING
		do
			Result := "def"
		end

	None_of_these: STRING = "none"

	object_count: INTEGER
		do
			Result := 42
		end

end
