note
	description: "Creation: named procedures, default_create, `create {T}', creation expressions, generic types."

class
	CREATION

create
	make

feature {NONE} -- Initialization

	make
		local
			p: POINT
			a: ANY
			thing: PLAIN
			list: LIST [STRING]
		do
			create p.make (1, 2)
			print ("make: " + p.out + "%N")
			create p.make_origin
			print ("make_origin: " + p.out + "%N")
			create p
			print ("default_create: " + p.out + "%N")
			p := create {POINT}.make (3, 4)
			print ("creation expression: " + p.out + "%N")
			create {POINT} a.make (5, 6)
			print ("create {T}: " + a.out + " " + a.generator + "%N")
			print ("inline: " + (create {POINT}.make (7, 8)).x.out + "%N")
			create thing
			thing.set_value (9)
			print ("no create clause: " + thing.value.out + "%N")
			create {ARRAYED_LIST [STRING]} list.make (2)
			list.extend ("generic")
			print ("create {ARRAYED_LIST [STRING]}: " + list.first + " " + list.generator + "%N")
			print ("each creation is new: " + (create {POINT}.make (1, 1) = create {POINT}.make (1, 1)).out + "%N")
			print ("attribute default: " + point.out + "%N")
		end

	point: POINT
		attribute
			create Result.make (10, 20)
		end

end
