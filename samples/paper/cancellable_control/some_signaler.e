note
	description: "[
		The signaler the paper's cancellable loop reads, `SOME_SIGNALER' in the paper: here the
		Thymio's proximity and ground sensors (a RANGE_SIGNALER).
	]"

class
	SOME_SIGNALER

inherit
	RANGE_SIGNALER

create
	make_thymio

end
