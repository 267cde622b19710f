note
	description: "Root class of the shapes program: polymorphism and dynamic binding."

class
	SHAPES_APP

inherit {NONE}
	EXECUTION_ENVIRONMENT

create
	make

feature {NONE} -- Initialization

	make
			-- Describe a list of shapes.
		local
			shapes: ARRAYED_LIST [SHAPE]
			r: RECTANGLE
			s: SQUARE
			a, b: COLORED_SQUARE
		do
			create shapes.make (4)
			create r.make (3.0, 4.0)
			shapes.extend (r)
			create s.make (2.0)
			s.scale (-1.5)
			shapes.extend (s)
			shapes.extend (create {CIRCLE}.make (1.0))
			create a.make (1.0, "red")
			create b.make (2.0, "blue")
			shapes.extend (a)
			across shapes as c loop
				c.item.describe
			end
			print ((a < b).out + " " + a.color_out + "%N")
			print (a.max (b).name + "%N")
		end

end
