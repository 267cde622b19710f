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
		external "Python" -- E: EXTERNAL
		alias "no_module_of_that_name.twice"
		end

end
