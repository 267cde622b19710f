class
	PAIR

end

class -- E: SYNTAX-CLASS@1
	SECOND_OF_PAIR

end
