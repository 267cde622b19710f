note
	description: "[
		A laser signaler that filters each scan with numpy (scan_sectors.py, beside this class) on
		its own processor: a median over five neighbouring beams removes single-beam spikes, then
		the nearest obstacle of each of four sectors (front, left, back, right) is kept.
	]"

class
	SECTOR_SCAN

inherit
	LASER_SIGNALER
		redefine
			on_scan
		end

create
	make

feature -- Access

	sector (i: INTEGER): REAL_64
			-- Nearest obstacle (m) in sector `i' (1 front, 2 left, 3 back, 4 right); +infinity for none.
		require
			valid_sector: 1 <= i and i <= 4
			scanned: filtered_count > 0
		do
			Result := sectors [i]
		end

	filtered_count: INTEGER
			-- Scans filtered so far.

feature -- Element change

	on_scan (a_angle_min, a_angle_increment, a_range_min, a_range_max, a_timestamp: REAL_64; a_ranges: ARRAY [REAL_64])
			-- <Precursor>
		do
			Precursor (a_angle_min, a_angle_increment, a_range_min, a_range_max, a_timestamp, a_ranges)
			sectors := nearest_by_sector (readings, a_angle_min, a_angle_increment, 4)
			filtered_count := filtered_count + 1
		end

feature {NONE} -- Implementation

	sectors: detachable ARRAY [REAL_64]
			-- Nearest obstacle per sector, from the last scan.

	nearest_by_sector (a_ranges: ARRAY [REAL_64]; a_angle_min, a_increment: REAL_64; a_count: INTEGER): ARRAY [REAL_64]
			-- Nearest range of each of `a_count' sectors centred on 0, 90, 180, 270 degrees, after
			-- a five-beam median filter.
		external
			"Python"
		alias
			"scan_sectors.nearest_by_sector"
		end

end
