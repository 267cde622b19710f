class
	BOAT

inherit
	VEHICLE
		redefine
			speed
		end

feature -- Access

	speed: INTEGER
		do
			Result := Precursor * 3
		end

end
