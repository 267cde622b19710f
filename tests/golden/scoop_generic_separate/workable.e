class WORKABLE
feature
	done: INTEGER
	work (n: INTEGER) do done := done + n end
end
