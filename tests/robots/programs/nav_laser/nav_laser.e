class
	NAV_LASER

create
	make

feature

	make
			-- Feed an unconnected LASER_SIGNALER one scan and print what it finds.
		local
			l: LASER_SIGNALER
			other: LASER_SIGNALER
			i: INTEGER
			s: STRING
		do
			create l.make_unconnected
				-- Ten beams, 36 degrees apart, from -180 degrees: two obstacles and a gap.
			l.on_scan (-{DOUBLE_MATH}.Pi, {DOUBLE_MATH}.Pi / 5.0, 0.0, 2.0, 1.0,
				<<1.0, 1.05, 1.1, 3.0, {REAL_64}.positive_infinity, 5.0, 0.5, 0.55, 0.6, 0.9>>)
			s := "segments"
			from i := 1 until i > l.beam_count loop
				s := s + " " + l.segment (i).out
				i := i + 1
			end
			print (s + " count " + l.segment_count.out + "%N")
			s := "endpoints"
			from i := 1 until i > l.endpoint_count loop
				s := s + " " + l.endpoint_beam (i).out + "/" + l.endpoint_side (i).out
				i := i + 1
			end
			print (s + "%N")
			print ("hit " + l.range (1).out + " nohit " + l.range (4).is_positive_infinity.out + "%N")
			print ("range_at 0 " + l.range_at (0.0).is_positive_infinity.out + " range_at 1.26 " + l.range_at (1.26).out + "%N")
			print ("min_range_in " + l.min_range_in (-3.2, -2.0).out + " " + l.min_range_in (0.5, 2.0).out + "%N")
			print ("nearest " + l.nearest_beam.out + " " + l.nearest_range.out + " in " + l.nearest_in (-1.0, 1.0).out + "%N")
			print ("corridor " + l.is_corridor_clear (0.0, 1.5, 0.2).out + " " + l.is_corridor_clear (1.5, 2.0, 0.2).out
				+ " clear " + ((l.clear_length (1.26, 0.2, 2.0) * 1000.0).rounded).out + "%N")
			create other.make_unconnected
			other.copy_scan (l)
			print ("copy " + other.beam_count.out + " " + other.endpoint_count.out + " " + other.range (10).out + "%N")
		end

end
