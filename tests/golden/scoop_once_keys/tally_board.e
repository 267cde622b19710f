class TALLY_BOARD
feature
	count: INTEGER
	add (n: INTEGER) do count := count + n end
end
