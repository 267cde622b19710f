class
	ACCOUNT

create
	make

feature {NONE} -- Initialization

	make (initial: INTEGER)
		require
			non_negative: initial >= 0
		do
			balance := initial
		ensure
			set: balance = initial
		end

feature -- Access

	balance: INTEGER

	history: ARRAYED_LIST [INTEGER]
		attribute
			create Result.make (4)
		end

feature -- Operations

	deposit (amount: INTEGER)
		require
			positive: amount > 0
		do
			balance := balance + amount
			history.extend (amount)
		ensure
			increased: balance = old balance + amount
			recorded: history.count = old history.count + 1
		end

	withdraw (amount: INTEGER)
		require
			positive: amount > 0
			enough: amount <= balance
		do
			balance := balance - amount
			history.extend (-amount)
		ensure
			decreased: balance = old balance - amount
		end

	faulty_deposit (amount: INTEGER)
			-- Adds one too many.
		do
			balance := balance + amount + 1
		ensure
			increased: balance = old balance + amount
		end

	doubled: INTEGER
		do
			Result := 2 * balance
		ensure
			twice: Result = balance * 2
			not_smaller: Result >= balance
		end

invariant
	non_negative_balance: balance >= 0

end
