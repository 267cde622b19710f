class
	GENERIC_LISTEN

create
	make

feature

	make
			-- Wait for three odometry messages, delivered as NAV_MSGS_ODOMETRY objects.
		local
			odometry: separate ODOMETRY_PRINTER
		do
			create odometry.make ("/odom")
			report (odometry)
		end

	report (o: separate ODOMETRY_PRINTER)
			-- Print what `o' saw once it saw three messages.
		require
			three: o.count >= 3
		do
			print ("frame " + create {STRING}.make_from_separate (o.frame) + ", x " + o.last_x.out + ", covariance " + o.covariance_count.out + "%N")
			o.close
		end

end
