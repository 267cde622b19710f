note
	description: "Follows the target that a tracker reports."

class
	FOLLOWER

create
	make

feature {NONE} -- Initialization

	make
			-- Create the tracker and read its target.
		do
			create tracker.make
			separate tracker as t do
				target := t.current_target -- E: VUER
				print (t.target_count)
			end
			print (target.distance)
		end

feature -- Access

	tracker: separate TRACKER
			-- The tracker, on its own processor.

	target: TARGET_INFO
			-- The target followed.

end
