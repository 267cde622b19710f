class
	BASE_ACCOUNT

create
	make

feature {NONE} -- Initialization

	make (initial: INTEGER)
		do
			balance := initial
		end

feature -- Access

	balance: INTEGER

feature -- Operations

	withdraw (amount: INTEGER)
		require
			positive: amount > 0
			covered: amount <= balance
		do
			balance := balance - amount
		ensure
			decreased: balance = old balance - amount
		end

	deposit (amount: INTEGER)
		require
			positive: amount > 0
		do
			balance := balance + amount
		ensure
			increased: balance = old balance + amount
		end

	fee: INTEGER
		do
			Result := 1
		ensure
			small: Result <= 5
		end

invariant
	not_too_negative: balance >= -100

end
