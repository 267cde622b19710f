class
	CAT

inherit
	ANIMAL

feature -- Access

	name: STRING
		do
			Result := "Tom"
		end

	sound: STRING
		do
			Result := "meow"
		end

end
