class
	AMPHIBIAN

inherit
	CAR
		rename
			speed as road_speed
		select
			road_speed
		end

	BOAT
		rename
			speed as water_speed
		end

feature -- Access

	both: STRING
		do
			Result := road_speed.out + "/" + water_speed.out
		end

end
