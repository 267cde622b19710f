note
	description: "Creation clauses and every form of creation instruction and creation expression."

class
	CREATION_FORMS

create
	make

create {CREATION_FORMS}
	make_with_name

create {NONE}
	make_empty, default_create

feature {NONE} -- Initialization

	make
			-- Create objects in every way.
		local
			s: STRING
			l: LIST [INTEGER]
			al: ARRAYED_LIST [INTEGER]
			other: CREATION_FORMS
			any: ANY
			n: INTEGER
		do
			create s.make (10)
			s.append ("made")
			create {ARRAYED_LIST [INTEGER]} l.make (5)
			l.extend (1)
			create al.make_from_array (<<1, 2, 3>>)
			create other.make_with_name ("other")
			create any
			create {STRING} any.make_from_string ("dynamic type STRING")
			s := create {STRING}.make_filled ('x', 3)
			n := (create {ARRAYED_LIST [INTEGER]}.make (4)).capacity
			print (s + " " + l.count.out + " " + al.count.out + " " + n.out + " " + other.name + "%N")
			print (create {STRING}.make_from_string ("expression argument"))
			print ("%N")
			print (any.out + "%N")
			create name.make_from_string ("root")
			print (name + "%N")
		end

	make_with_name (a_name: STRING)
			-- Create with `a_name'.
		do
			name := a_name
		end

	make_empty
			-- Create with an empty name.
		do
			create name.make_empty
		end

feature -- Access

	name: STRING
			-- A name.
		attribute
			Result := ""
		end

end
