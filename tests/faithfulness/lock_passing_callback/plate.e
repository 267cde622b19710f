class
	PLATE

create
	make

feature

	make (n: CHARACTER)
		do
			name := n
		end

	name: CHARACTER

	take (d: separate DINER)
			-- Report that `d` takes Current: `d.id` is a callback into the diner's region,
			-- valid because the diner passed its lock with `Current`.
		do
			print ("plate " + name.out + " taken by " + d.id.out + "%N")
		end

	give_back (d: separate DINER)
		do
			print ("plate " + name.out + " given back by " + d.id.out + "%N")
		end

end
