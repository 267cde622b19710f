note
	description: "Root class: set the table, start every philosopher, then count the meals."

class
	DINING_TABLE

create
	make

feature {NONE} -- Initialization

	make
			-- Seat `Size' philosophers.
		local
			forks: ARRAYED_LIST [separate FORK]
			philosophers: ARRAYED_LIST [separate PHILOSOPHER]
			f: separate FORK
			p: separate PHILOSOPHER
			i: INTEGER
		do
			create forks.make (Size)
			from i := 1 until i > Size loop
				create f.make (i)
				forks.extend (f)
				i := i + 1
			end
			create philosophers.make (Size)
			across 1 |..| Size as k loop
				create p.make (k.item, forks [k.item], forks [k.item \\ Size + 1], Rounds)
				philosophers.extend (p)
			end
			across philosophers as c loop
				start (c.item)
			end
			across forks as c loop
				report (c.item)
			end
		end

feature -- Constants

	Size: INTEGER = 5
	Rounds: INTEGER = 20

feature {NONE} -- Implementation

	start (p: separate PHILOSOPHER)
			-- Let `p' live.
		do
			p.live
		end

	report (f: separate FORK)
			-- Print how often `f' was used.
		do
			print ("fork " + f.id.out + ": " + f.uses.out + "%N")
		end

end
