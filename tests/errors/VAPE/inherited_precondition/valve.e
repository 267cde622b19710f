class
	VALVE

feature {VALVE} -- Basic operations

	open
			-- Open the valve; only valves call it, so only valves need to test `is_safe'.
		require
			safe: is_safe -- E: VAPE@10
		do
		end

feature {VALVE} -- Status

	is_safe: BOOLEAN
			-- Is it safe to open?
		do
			Result := True
		end

end
