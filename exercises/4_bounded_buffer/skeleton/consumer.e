note
	description: "[
		Takes `total' numbers out of a shared buffer and keeps them in `received' (exercise 4).
		Complete `consume': each take must wait until the buffer is not empty.
	]"

class
	CONSUMER

create
	make

feature {NONE} -- Initialization

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; a_total: INTEGER)
			-- A consumer of `a_total' numbers from `a_buffer'.
		do
			buffer := a_buffer
			total := a_total
			create received.make (a_total)
		end

feature -- Access

	buffer: separate BOUNDED_BUFFER [INTEGER]
			-- Where the numbers come from.

	total: INTEGER
			-- How many to take.

	received: ARRAYED_LIST [INTEGER]
			-- The numbers taken, in the order they came.

	sum: INTEGER
			-- Their sum.
		do
			across received as r loop
				Result := Result + r.item
			end
		end

feature -- Status report

	is_done: BOOLEAN
			-- Has it taken all `total' numbers?
		do
			Result := received.count = total
		end

feature -- Basic operations

	consume
			-- Take `total' numbers out of `buffer' (each the oldest there), into `received'.
		do
			-- TODO
		ensure
			done: is_done
		end

end
