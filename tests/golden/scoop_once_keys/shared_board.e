class SHARED_BOARD
feature
	board: separate TALLY_BOARD
		once ("PROCESS")
			create Result
		end
end
