deferred class
	ANIMAL

feature -- Access

	name: STRING
		deferred
		end

	sound: STRING
		deferred
		end

	describe: STRING
		do
			Result := name + " says " + sound
		end

end
