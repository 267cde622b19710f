note
	description: "Multiple and repeated inheritance: rename, redefine, undefine, select, Precursor, dynamic binding."

class
	INHERITANCE

create
	make

feature {NONE} -- Initialization

	make
		local
			shapes: ARRAYED_LIST [SHAPE]
			cs: COLORED_SQUARE
			c: COLORED
			v: VEHICLE
			b: BOAT
			amphibian: AMPHIBIAN
		do
			create shapes.make (3)
			shapes.extend (create {RECTANGLE}.make (2, 3))
			shapes.extend (create {SQUARE}.make (4))
			create cs.make_colored (1.5, "red")
			shapes.extend (cs)
			across shapes is s loop
				print (s.describe + "%N")
			end
			c := cs
			print ("as COLORED: " + c.describe + " / " + c.name + "%N")
			print ("color_description: " + cs.color_description + "%N")
			create {CAR} v
			print (v.describe + "%N")
			create {BOAT} v
			print (v.describe + "%N")
			create amphibian
			v := amphibian
			b := amphibian
			print ("amphibian as VEHICLE: " + v.speed.out + ", " + v.describe + "%N")
			print ("amphibian as BOAT: " + b.speed.out + "%N")
			print ("amphibian: " + amphibian.both + "%N")
		end

end
