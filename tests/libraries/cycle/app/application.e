class
	APPLICATION

create
	make

feature

	make
		do
			print ((create {LEFT_PART}).name + " " + (create {RIGHT_PART}).name + "%N")
		end

end
