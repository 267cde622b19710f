class
	DOG

inherit
	ANIMAL

feature -- Access

	name: STRING = "Rex"

	sound: STRING
		do
			Result := "woof"
		end

	fetch: STRING
		do
			Result := name + " fetches"
		end

end
