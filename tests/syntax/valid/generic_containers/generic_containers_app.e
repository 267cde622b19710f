note
	description: "Root class: generic derivations of BOUNDED_STACK, SORTED_PAIR and REGISTRY."

class
	GENERIC_CONTAINERS_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Use the generic classes with several actual types.
		local
			ints: BOUNDED_STACK [INTEGER]
			names: BOUNDED_STACK [STRING]
			pair: SORTED_PAIR [STRING]
			reg: REGISTRY [STRING, TALLY, REAL_64]
			stacks: ARRAYED_LIST [BOUNDED_STACK [detachable STRING]]
		do
			create ints.make (3)
			ints.push (1)
			ints.push (2)
			print (ints.mapped (agent (n: INTEGER): INTEGER do Result := n * 10 end).out + "%N")
			create names.make (2)
			names.push ("x")
			print (names.top_or_default ("none") + "%N")
			create pair.make ("pear", "apple")
			print (pair.low + " " + pair.contains ("banana").out + "%N")
			create reg.make
			reg.value_for ("a").increment
			print (reg.value_for ("a").count.out + "%N")
			if attached reg.smallest_key as k then
				print (k + "%N")
			end
			create stacks.make (1)
			stacks.extend (create {BOUNDED_STACK [detachable STRING]}.make (1))
			print (stacks.first.count.out + "%N")
		end

end
