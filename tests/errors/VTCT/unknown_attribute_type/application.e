class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Start drawing.
		do
			print ("drawing%N")
		end

feature -- Access

	current_shape: detachable SHAPE -- E: VTCT
			-- The shape being drawn (there is no class SHAPE).

end
