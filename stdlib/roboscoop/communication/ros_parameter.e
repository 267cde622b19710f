note
	description: "[
		A parameter of the program's ROS 2 node (`ros2 param list/get/set/describe'): a BOOLEAN, an
		INTEGER, a REAL_64 or a STRING named `name', declared with a default when created
		(`make_with_text' for a STRING made on another processor). `item' can be read in wait
		conditions; a change from outside (`ros2 param set') arrives as an asynchronous
		call on this object's processor (`change_count' counts them). Without a ROS 2 robot the
		parameter just keeps its value.
	]"

class
	ROS_PARAMETER [G]

create
	make,
	make_with_text

feature {NONE} -- Initialization

	make (a_name: separate STRING; a_default: G; a_description: separate STRING)
			-- Parameter `a_name' ("speed", "nav.max_speed") of the program's node, `a_default' first.
		do
			create name.make_from_separate (a_name)
			create description.make_from_separate (a_description)
			item := a_default
			declare_parameter
		ensure
			default_set: item = a_default
		end

	make_with_text (a_name, a_default, a_description: separate STRING)
			-- STRING parameter `a_name', `a_default' first. (`make' cannot take a STRING made on
			-- another processor: use this one to create a ROS_PARAMETER [STRING] as a separate object.)
		local
			l_text: STRING
		do
			create name.make_from_separate (a_name)
			create description.make_from_separate (a_description)
			create l_text.make_from_separate (a_default)
			check
				string_parameter: attached {G} l_text as l_item
			then
				item := l_item
			end
			declare_parameter
		end

feature -- Access

	name: STRING
			-- The parameter's name.

	description: STRING
			-- What it is for (`ros2 param describe').

	item: G
			-- The current value.

	change_count: INTEGER
			-- Changes from outside so far.

feature -- Element change

	set_item (a_value: G)
			-- Make `a_value' the value (the node's parameter too).
		do
			item := a_value
			publish_item
		ensure
			set: item = a_value
		end

feature {NONE} -- Transport

	on_change (a_value: G)
			-- Called on this processor when the parameter is set from outside.
		do
			item := a_value
			change_count := change_count + 1
		end

	declare_parameter
			-- Declare it in the node's parameters.
		external
			"Python"
		end

	publish_item
			-- Tell the node's parameters the new `item'.
		external
			"Python"
		end

end
