note
	description: "Uses a library (shapes) whose .ecf names another library (units)."

class
	APPLICATION

create
	make

feature

	make
		local
			r: RECTANGLE
			l: LENGTH
		do
			create l.make_centimetres (250)
			create r.make (l, create {LENGTH}.make_centimetres (40))
			print ("width: " + r.width.out + "%N")
			print ("height: " + r.height.out + "%N")
			print ("perimeter: " + r.perimeter.out + "%N")
		end

end
