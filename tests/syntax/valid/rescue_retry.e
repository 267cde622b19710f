note
	description: "Exception handling: rescue clauses, retry, and raising an exception."

class
	RESCUE_RETRY

create
	make

feature {NONE} -- Initialization

	make
			-- Call a routine that fails twice before it succeeds.
		do
			print (attempt_division (10, 0).out + "%N")
			print (resilient_parse ("123").out + "%N")
			print (failures.out + "%N")
			safe_call
		end

feature -- Access

	failures: INTEGER
			-- How many times a rescue clause ran.

feature -- Operations

	attempt_division (a, b: INTEGER): INTEGER
			-- `a' divided by `b', or by 1 after a failure.
		local
			divisor: INTEGER
			retried: BOOLEAN
		do
			if retried then
				divisor := 1
			else
				divisor := b
			end
			if divisor = 0 then
				(create {DEVELOPER_EXCEPTION}).raise
			end
			Result := a // divisor
		rescue
			failures := failures + 1
			retried := True
			retry
		end

	resilient_parse (s: STRING): INTEGER
			-- `s' as an integer, trying at most three times.
		local
			attempts: INTEGER
		do
			attempts := attempts + 1
			if attempts < 3 then
				raise_problem ("try again")
			end
			Result := s.to_integer
		rescue
			failures := failures + 1
			if attempts < 3 then
				retry
			end
		end

	safe_call
			-- A routine whose rescue clause gives up without retrying.
		local
			done: BOOLEAN
		do
			if not done then
				raise_problem ("first attempt")
			end
			print ("safe_call done%N")
		rescue
			print ("rescued%N")
			done := True
			retry
		end

	raise_problem (message: STRING)
			-- Raise a developer exception with `message'.
		local
			e: DEVELOPER_EXCEPTION
		do
			create e
			e.set_description (message)
			e.raise
		end

end
