class
	DRIVE

create
	make

feature

	make
			-- Send two commands, the second beyond the limits.
		local
			d: DIFFERENTIAL_DRIVE
		do
			create d.make ("/robot1/cmd_vel", 0.5, 1.0)
			d.send (0.25, -0.5)
			d.send (3.0, 2.0)
			print ("sent " + d.command_count.out + " " + d.linear.out + " " + d.angular.out + "%N")
		end

end
