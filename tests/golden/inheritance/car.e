class
	CAR

inherit
	VEHICLE
		redefine
			speed
		end

feature -- Access

	speed: INTEGER
		do
			Result := 100
		end

end
