note
	description: "A routine written right after the creation clause, without a `feature' keyword."

class
	ROUTINE_BEFORE_FEATURE_KEYWORD

create
	make

	make -- E: SYNTAX
		do
			print ("hello%N")
		end

end
