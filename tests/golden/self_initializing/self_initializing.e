note
	description: "[
		Self-initializing attributes (ECMA-367 8.19, EiffelStudio): the `attribute' body runs when
		an attached attribute is read while still Void, once; never for an attribute that was set,
		for a detachable attribute or for an expanded one.
	]"

class
	SELF_INITIALIZING

create
	make

feature {NONE} -- Initialization

	make
		local
			a, b: LAZY_PARTS
			h: HOLDER [INTEGER]
		do
			create a.make
			print ("first read: " + a.name + "%N")
			print ("second read: " + a.name + "%N")
			create b.make_named ("given")
			print ("set by creation: " + b.name + "%N")
			a.parts.extend (1)
			a.parts.extend (2)
			print ("parts: " + a.parts.count.out + "%N")
			print ("count: " + a.count.out + "%N")
			if attached a.label as l then
				print ("label: " + l + "%N")
			else
				print ("label: Void%N")
			end
			create h
			print ("expanded actual generic: " + h.content.out + "%N")
		end

end
