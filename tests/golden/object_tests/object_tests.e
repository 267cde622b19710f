note
	description: "Object tests (typed and untyped), assignment attempts, conformance of generic types."

class
	OBJECT_TESTS

create
	make

feature {NONE} -- Initialization

	make
		local
			a: ANIMAL
			x: ANY
			s: detachable STRING
			zoo: ARRAYED_LIST [ANIMAL]
			n: detachable DOG
			dogs: INTEGER
		do
			create {DOG} a
			if attached {DOG} a as d then
				print ("a dog: " + d.fetch + "%N")
			end
			if attached {CAT} a as c then
				print ("a cat: " + c.name + "%N")
			else
				print ("not a cat%N")
			end
			if not attached {CAT} a then
				print ("still not a cat%N")
			end
			x := 42
			if attached {INTEGER} x as i then
				print ("an integer: " + (i + 1).out + "%N")
			end
			if attached {STRING} x then
				print ("a string%N")
			else
				print ("not a string%N")
			end
			x := "text"
			if attached {STRING} x as str then
				print ("a string of " + str.count.out + "%N")
			end
			print ("Void attached: " + (attached s).out + "%N")
			s := "here"
			if attached s as t and then t.count = 4 then
				print ("attached local: " + t + "%N")
			end
			create zoo.make (3)
			zoo.extend (a)
			zoo.extend (create {CAT})
			zoo.extend (create {DOG})
			across zoo is z loop
				if attached {DOG} z then
					dogs := dogs + 1
				end
				print (z.describe + " (" + z.generator + ")%N")
			end
			print ("dogs: " + dogs.out + "%N")
			n ?= zoo [2]
			print ("attempt on a cat: " + (n = Void).out + "%N")
			n ?= zoo [3]
			print ("attempt on a dog: " + (n /= Void).out + "%N")
			x := zoo
			print ("generics: " + (attached {LIST [ANIMAL]} x).out + " " + (attached {LIST [DOG]} x).out + " "
				+ (attached {ARRAYED_LIST [ANIMAL]} x).out + " " + (attached {LINKED_LIST [ANIMAL]} x).out + "%N")
			print ("generator: " + x.generator + "%N")
			print ("same_type: " + a.same_type (zoo [3]).out + " " + a.same_type (zoo [2]).out + "%N")
			print ("conforms_to: " + a.conforms_to (zoo [3]).out + " " + a.conforms_to (zoo [2]).out + "%N")
		end

end
