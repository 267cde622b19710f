class
	NAV_SCAN

create
	make

feature

	make
			-- Print what a LASER_SIGNALER made of the scan stamped 4.5 s on /scan.
		local
			l: separate LASER_SIGNALER
		do
			create l.make ("/scan")
			report (l)
		end

	report (l: separate LASER_SIGNALER)
			-- Report once the last scan of the test arrived.
		require
			l.timestamp = 4.5
		do
			print ("beams " + l.beam_count.out + " min " + l.angle_min.out + " inc " + l.angle_increment.out
				+ " max " + l.range_max.out + "%N")
			print ("ranges " + l.range (1).out + " " + l.range (2).out + " " + l.range (3).out + " " + l.range (4).out + "%N")
			print ("stale " + l.is_stale.out + " updates>0 " + (l.update_count > 0).out + "%N")
			l.close
		end

end
