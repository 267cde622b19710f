note
	description: "Introduces a robot by its name."

class
	GREETER

create
	make

feature {NONE} -- Initialization

	make
			-- Create a robot and introduce it.
		local
			l_robot: separate ROBOT
		do
			create l_robot.make ("Thymio")
			introduce (l_robot)
		end

feature -- Basic operations

	introduce (a_robot: separate ROBOT)
			-- Print the name of `a_robot'.
		local
			l_name: STRING
		do
			io.put_string (a_robot.name) -- E: VUAR(2)
			io.put_new_line
			create l_name.make_from_separate (a_robot.name)
			io.put_string (l_name)
			io.put_new_line
			print (a_robot.name.count)
			io.put_new_line
			print ("battery " + a_robot.battery.out + "%N")
		end

end
