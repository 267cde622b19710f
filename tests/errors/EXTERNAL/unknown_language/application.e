class
	APPLICATION

create
	make

feature

	make
		do
			print (twice (2))
		end

	twice (x: INTEGER): INTEGER
		external "Fortran" -- E: EXTERNAL
		end

end
