class
	VEHICLE

feature -- Access

	speed: INTEGER
		do
			Result := 10
		end

	describe: STRING
		do
			Result := generator.as_lower + " at " + speed.out
		end

end
