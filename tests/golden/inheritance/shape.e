deferred class
	SHAPE

feature -- Access

	area: REAL_64
		deferred
		end

	name: STRING
		deferred
		end

	describe: STRING
		do
			Result := name + " of area " + area.out
		end

end
