note
	description: "An inherit clause placed after the features."

class
	INHERIT_AFTER_FEATURE

create
	make

feature {NONE} -- Initialization

	make
		do
			print (out)
		end

inherit -- E: SYNTAX
	ANY

end
