class
	LEFT_PART

feature

	name: STRING = "left"

end
