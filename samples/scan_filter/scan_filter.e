note
	description: "[
		A laser scan filtered with numpy from a signaler: SECTOR_SCAN, a LASER_SIGNALER on its own
		processor, removes single-beam spikes and finds the nearest obstacle in each of four
		sectors with a Python function of `scan_sectors.py' (beside this class) every time a scan
		arrives. The root reads the sectors five times, a second apart, and stops.
	]"

class
	SCAN_FILTER

create
	make

feature {NONE} -- Initialization

	make
			-- Report the nearest obstacles `Reports' times.
		local
			env: ROBOT_ENVIRONMENT
			scan: separate SECTOR_SCAN
			clock: TIMER
			i: INTEGER
		do
			create env
			create clock.make
			create scan.make (env.namespace + "/scan")
			from i := 1 until i > Reports loop
				clock.sleep (1.0)
				report (i, scan)
				i := i + 1
			end
		end

feature {NONE} -- Implementation

	Reports: INTEGER = 5
			-- How many times the sectors are read.

	report (a_index: INTEGER; a_scan: separate SECTOR_SCAN)
			-- Print the nearest obstacle of each sector, once `a_scan' has had a scan.
		require
			scanned: a_scan.filtered_count > 0
		do
			print ("scan " + a_index.out + ": nearest obstacle front " + metres (a_scan.sector (1))
				+ ", left " + metres (a_scan.sector (2)) + ", back " + metres (a_scan.sector (3))
				+ ", right " + metres (a_scan.sector (4)) + " (" + a_scan.filtered_count.out + " scans filtered)%N")
		end

	metres (v: REAL_64): STRING
			-- `v' in metres with two decimals, or "none" for no obstacle.
		local
			cm: INTEGER
		do
			if v.is_nan or v > 1.0e6 then
				Result := "none"
			else
				cm := (v * 100.0).rounded
				Result := (cm // 100).out + "." + ((cm \\ 100) // 10).out + (cm \\ 10).out + " m"
			end
		end

end
