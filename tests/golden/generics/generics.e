note
	description: "Generic classes: constrained genericity, creation on a formal, `like Current', defaults of formals."

class
	GENERICS

create
	make

feature {NONE} -- Initialization

	make
		local
			ib: BOX [INTEGER]
			sb: BOX [STRING]
			lb: LABELED_BOX [INTEGER]
			p: ORDERED_PAIR [INTEGER]
			q: ORDERED_PAIR [STRING]
			f: FACTORY [COUNTER]
			rb: BOX [INTEGER]
			real_box: BOX [REAL]
		do
			create ib.make_empty
			create sb.make_empty
			print ("defaults: " + ib.item.out + " " + (sb.item = Void).out + "%N")
			create ib.make (21)
			print ("mapped: " + ib.mapped (agent (x: INTEGER): INTEGER do Result := x * 2 end).item.out + "%N")
			create lb.make_labeled (7, "seven")
			rb := lb.replaced (8)
			print ("like Current: " + rb.generator + " " + rb.item.out + " " + lb.item.out + "%N")
			if attached {LABELED_BOX [INTEGER]} rb as l then
				print ("label kept: " + l.label + "%N")
			end
			create p.make (9, 3)
			print ("pair: " + p.low.out + " " + p.high.out + " " + p.contains (5).out + " " + p.contains (10).out + "%N")
			create q.make ("pear", "apple")
			print ("strings: " + q.low + " " + q.high + " " + q.contains ("banana").out + "%N")
			create f
			print ("created on formal: " + f.new_default.value.out + " " + f.new_at (5).value.out + "%N")
			print ("generating types: " + ib.generating_type.name + "%N")
			create real_box.make (0.1)
			print ("images: " + real_box.image + ", " + ib.image + ", " + sb.image + ", " + q.low + "%N")
		end

end
