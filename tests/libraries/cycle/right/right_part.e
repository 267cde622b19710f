class
	RIGHT_PART

feature

	name: STRING = "right"

end
