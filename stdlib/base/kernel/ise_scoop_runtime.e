note
	description: "[
		Access to the SCOOP runtime: the region (processor) an object belongs to.
		Pinning processors to threads is accepted and has no effect: the runtime
		schedules processors itself.
	]"

class
	ISE_SCOOP_RUNTIME

feature -- Access

	invalid_region_id: NATURAL_16 = 0xFFFF
			-- Region identifier that no region has.

	region_id (a_object: separate ANY): NATURAL_16
			-- Identifier of the region (processor) that `a_object' belongs to.
		external
			"Python"
		end

feature -- Basic operations

	pin_to_thread
			-- Keep the current processor on its own thread (no effect).
		do
		end

	pin_processor_to_thread (a_object: separate ANY)
			-- Keep the processor of `a_object' on its own thread (no effect).
		do
		end

end
