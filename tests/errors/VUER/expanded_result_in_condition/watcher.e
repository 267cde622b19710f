note
	description: "Watches the temperature reported by a station."

class
	WATCHER

create
	make

feature {NONE} -- Initialization

	make
			-- Create a station and watch it.
		local
			l_station: separate STATION
		do
			create l_station.make
			watch (l_station)
		end

feature -- Basic operations

	watch (a_station: separate STATION)
			-- Warn when `a_station' reports a high temperature.
		do
			if a_station.latest.value > 30 then -- E: VUER
				print ("hot%N")
			end
			if a_station.latest_value > 30 then
				print ("still hot%N")
			end
		end

end
