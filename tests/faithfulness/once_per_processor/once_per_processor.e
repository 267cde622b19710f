class
	ONCE_PER_PROCESSOR

create
	make

feature

	make
			-- Three greeters on their own processors, each with its own `name` (a once).
		local
			g: separate GREETER
		do
			across 1 |..| 3 as i loop
				create g.make (i.item)
				greet (g)
			end
		end

	greet (g: separate GREETER)
		do
			g.greet
		end

end
