note
	description: "A feature clause placed after the class invariant."

class
	FEATURE_AFTER_INVARIANT

create
	make

feature {NONE} -- Initialization

	make
		do
			count := 1
		end

invariant
	count_positive: count >= 0

feature -- Access -- E: SYNTAX

	count: INTEGER

end
