note
	description: "[
		A PID controller: output = kp * e + ki * integral (e) + kd * de/dt, clamped to
		[-output_limit, output_limit] (no limit when `output_limit' = 0); the integral is not
		accumulated while the output saturates (anti-windup).
	]"

class
	PID_CONTROLLER

create
	make

feature {NONE} -- Initialization

	make (a_kp, a_ki, a_kd: REAL_64)
			-- Controller with gains `a_kp', `a_ki', `a_kd'.
		do
			kp := a_kp
			ki := a_ki
			kd := a_kd
		ensure
			fresh: not has_previous and integral = 0.0
		end

feature -- Access

	kp, ki, kd: REAL_64
			-- Gains.

	output_limit: REAL_64
			-- Largest magnitude of the output (0: none).

	integral: REAL_64
			-- Accumulated error x time.

	previous_error: REAL_64
			-- Error at the last `output'.

	has_previous: BOOLEAN
			-- Has `output' been called since `make' or `reset'?

	last_output: REAL_64
			-- Result of the last `output'.

feature -- Basic operations

	output (a_error, a_dt: REAL_64): REAL_64
			-- Control output for `a_error' after `a_dt' seconds since the previous call.
		require
			positive_dt: a_dt > 0.0
		local
			derivative, candidate: REAL_64
		do
			if has_previous then
				derivative := (a_error - previous_error) / a_dt
			end
			candidate := kp * a_error + ki * (integral + a_error * a_dt) + kd * derivative
			if output_limit > 0.0 and then candidate.abs > output_limit then
				Result := clamped (kp * a_error + ki * integral + kd * derivative)
			else
				integral := integral + a_error * a_dt
				Result := candidate
			end
			previous_error := a_error
			has_previous := True
			last_output := Result
		ensure
			limited: output_limit > 0.0 implies Result.abs <= output_limit
			remembered: previous_error = a_error and has_previous
		end

	reset
			-- Forget the integral and the previous error.
		do
			integral := 0.0
			previous_error := 0.0
			has_previous := False
			last_output := 0.0
		ensure
			fresh: not has_previous and integral = 0.0
		end

feature -- Element change

	set_output_limit (a_limit: REAL_64)
			-- Clamp outputs to [-`a_limit', `a_limit'] (0: no limit).
		require
			non_negative: a_limit >= 0.0
		do
			output_limit := a_limit
		end

	set_gains (a_kp, a_ki, a_kd: REAL_64)
			-- New gains.
		do
			kp := a_kp
			ki := a_ki
			kd := a_kd
		end

feature {NONE} -- Implementation

	clamped (v: REAL_64): REAL_64
			-- `v' within the output limit.
		do
			Result := v.max (- output_limit).min (output_limit)
		end

end
