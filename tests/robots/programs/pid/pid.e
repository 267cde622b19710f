class
	PID

create
	make

feature

	make
			-- Outputs of a P, a PI, a PD and a limited controller.
		local
			c: PID_CONTROLLER
		do
			create c.make (2.0, 0.0, 0.0)
			print (c.output (1.5, 0.1).out + "%N")
			create c.make (1.0, 0.5, 0.0)
			print (c.output (1.0, 1.0).out + " " + c.output (1.0, 1.0).out + "%N")
			create c.make (1.0, 0.0, 0.5)
			print (c.output (1.0, 0.5).out + " " + c.output (2.0, 0.5).out + "%N")
			create c.make (10.0, 1.0, 0.0)
			c.set_output_limit (2.0)
			print (c.output (1.0, 1.0).out + " " + c.output (-1.0, 1.0).out + " " + c.integral.out + "%N")
			c.reset
			print (c.has_previous.out + "%N")
		end

end
