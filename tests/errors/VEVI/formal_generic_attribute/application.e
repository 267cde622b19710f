class
	APPLICATION

create
	make

feature {NONE} -- Initialization

	make
			-- Make an empty box.
		local
			b: BOX [STRING]
		do
			create b.make
			print (b.count)
		end

end
