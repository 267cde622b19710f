note
	description: "[
		The paper's `move_limbs' as a program: an arm and a leg, each on its own processor, moved in
		one routine that reserves both, so the two moves form one action. `move_limbs' is the
		paper's routine; the rest is its frame: the limbs and a walk of three steps.
	]"

class
	MOVE_LIMBS

create
	make

feature {NONE} -- Initialization

	make
			-- Take three steps, then say how often each limb moved.
		local
			arm: separate ARM
			leg: separate LEG
			i: INTEGER
		do
			create arm.make
			create leg.make
			from i := 1 until i > 3 loop
				move_limbs (arm, leg)
				i := i + 1
			end
			report (arm, leg)
		end

feature -- The paper's listing

	move_limbs (arm: separate ARM; leg: separate LEG)
		do
			arm.move
			leg.move
		end

feature {NONE} -- Frame

	report (a_arm: separate ARM; a_leg: separate LEG)
			-- Say how often each limb moved.
		do
			print ("Limbs moved: arm " + a_arm.move_count.out + ", leg " + a_leg.move_count.out + "%N")
		end

end
