class
	IMU_LISTEN

create
	make

feature

	make
			-- Print the first IMU message's values (SENSOR_MSGS_IMU comes from `scoopc msg').
		local
			printer: separate IMU_PRINTER
		do
			create printer.make
			report (printer)
		end

	report (p: separate IMU_PRINTER)
			-- Print what `p' received, once it has.
		require
			received: p.has_message
		do
			print ("imu z " + p.acceleration_z.out + " w " + p.orientation_w.out + "%N")
			p.close
		end

end
