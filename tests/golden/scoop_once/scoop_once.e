note
	description: "once routines are per region by default; once (%"PROCESS%") is global."

class
	SCOOP_ONCE

create
	make

feature {NONE} -- Initialization

	make
		local
			s1, s2: separate STAMPER
			s3, s4: STAMPER
		do
			create s1
			create s2
			create s3
			create s4
			stamp (s1, 1)
			stamp (s1, 2)
			stamp (s2, 3)
			s3.stamp (4)
			s4.stamp (5)
			print ("stamps: " + count (s1).out + " " + count (s2).out + " " + s3.stamps.count.out + " " + s4.stamps.count.out + "%N")
			print ("region tags: " + region_tag (s1, 10).out + " " + region_tag (s2, 20).out + " " + region_tag (s1, 30).out + " " + s3.region_tag (40).out + " " + s4.region_tag (50).out + "%N")
			print ("process tags: " + process_tag (s1, 10).out + " " + process_tag (s2, 20).out + " " + s3.process_tag (40).out + "%N")
		end

feature {NONE} -- Implementation

	stamp (s: separate STAMPER; v: INTEGER)
		do
			s.stamp (v)
		end

	count (s: separate STAMPER): INTEGER
		do
			Result := s.stamps.count
		end

	region_tag (s: separate STAMPER; t: INTEGER): INTEGER
		do
			Result := s.region_tag (t)
		end

	process_tag (s: separate STAMPER; t: INTEGER): INTEGER
		do
			Result := s.process_tag (t)
		end

end
