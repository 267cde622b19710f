note
	description: "twin, copy, deep_twin, is_equal redefined, standard_is_equal, equal, `=' and `~', assigners."

class
	COPY_EQUALITY

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b, c: NODE
		do
			create a.make (1, "a")
			a.add (create {NODE}.make (2, "child"))
			b := a.twin
			print ("twin: " + (a = b).out + " " + (a ~ b).out + " copies " + b.copies.out + " shares children " + (a.children = b.children).out + "%N")
			c := a.deep_twin
			print ("deep_twin: " + (a.children = c.children).out + " " + (a.children.first = c.children.first).out + " " + (a.children.first.label ~ c.children.first.label).out + " " + a.is_deep_equal (c).out + "%N")
			create c.make (1, "other")
			print ("is_equal redefined: " + (a ~ c).out + " " + a.is_equal (c).out + " standard " + a.standard_is_equal (c).out + "%N")
			c.value := 5
			print ("assigner: " + c.value.out + " " + (a ~ c).out + "%N")
			c.copy (a)
			print ("copy: " + c.value.out + " " + c.label + " " + (c ~ a).out + " copies " + c.copies.out + "%N")
			print ("equal: " + equal (a, c).out + " " + equal (a, Void).out + " " + deep_equal (a, a.deep_twin).out + "%N")
			print ("strings: " + ("abc").twin.same_string ("abc").out + "%N")
		end

end
