note
	description: "Adds up the partial sums it is sent."

class
	ACCUMULATOR

create
	make

feature {NONE} -- Initialization

	make
			-- Accumulator at zero.
		do
			sum := 0
		end

feature -- Access

	sum: INTEGER
			-- Total of the partial sums.

	contributions: INTEGER
			-- Number of partial sums added.

feature -- Element change

	add (a_part: INTEGER)
			-- Add the partial sum `a_part'.
		do
			sum := sum + a_part
			contributions := contributions + 1
		ensure
			added: sum = old sum + a_part
			counted: contributions = old contributions + 1
		end

end
